#include "gltf/json_check.h"

#include <nlohmann/json.hpp>

#include "io/input_error.h"

namespace patina::gltf {

namespace {

using SaxJson = nlohmann::json;

// Counts as it goes and stops the parse at the first broken rule; no document is built.
class Checker final : public nlohmann::json_sax<SaxJson> {
public:
    explicit Checker(bool glb) : glb_(glb) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }

    bool start_object(std::size_t) override {
        if (++objects_ > kMaxJsonObjects) {
            return stop("more than " + std::to_string(kMaxJsonObjects) + " objects");
        }
        if (!enter()) {
            return false;
        }
        if (inBuffers_ && depth_ == 3) {
            bufferHasUri_ = false;
        }
        return true;
    }
    bool key(string_t& key) override {
        if (depth_ == 1) {
            rootKey_ = key;
        } else if (inBuffers_ && depth_ == 3 && key == "uri") {
            bufferHasUri_ = true;
        }
        return true;
    }
    bool end_object() override {
        if (inBuffers_ && depth_ == 3) {
            if (glb_ && !bufferHasUri_ && buffer_ > 0) {
                return stop("/buffers/" + std::to_string(buffer_) +
                            ": only buffers[0] may take its data from the GLB's BIN chunk "
                            "(this buffer has no uri)");
            }
            ++buffer_;
        }
        --depth_;
        return true;
    }
    bool start_array(std::size_t) override {
        if (!enter()) {
            return false;
        }
        if (depth_ == 2 && rootKey_ == "buffers") {
            inBuffers_ = true;
        }
        return true;
    }
    bool end_array() override {
        if (depth_ == 2) {
            inBuffers_ = false;
        }
        --depth_;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
        std::string what = error.what();
        // Drop nlohmann's "[json.exception.parse_error.101] ".
        if (const size_t bracket = what.find("] "); bracket != std::string::npos) {
            what = what.substr(bracket + 2);
        }
        return stop("invalid JSON: " + what);
    }

    const std::string& problem() const { return problem_; }

private:
    bool value() {
        return ++values_ <= kMaxJsonValues ||
               stop("more than " + std::to_string(kMaxJsonValues) + " JSON values");
    }
    bool enter() {
        if (!value()) {
            return false;
        }
        return ++depth_ <= kMaxJsonDepth ||
               stop("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    bool stop(const std::string& problem) {
        if (problem_.empty()) {
            problem_ = problem;
        }
        return false;
    }

    bool glb_;
    size_t depth_ = 0, values_ = 0, objects_ = 0;
    std::string rootKey_;
    bool inBuffers_ = false, bufferHasUri_ = false;
    size_t buffer_ = 0;
    std::string problem_;
};

}  // namespace

void checkGltfJson(std::string_view json, bool glb, const std::string& source) {
    Checker checker(glb);
    if (!SaxJson::sax_parse(json.begin(), json.end(), &checker)) {
        throw InputError(source + ": " + (checker.problem().empty() ? "invalid JSON" : checker.problem()));
    }
}

}  // namespace patina::gltf
