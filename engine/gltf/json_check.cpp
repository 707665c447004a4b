#include "gltf/json_check.h"

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf/json_rules.h"
#include "gltf/meshopt.h"
#include "files/input_error.h"

namespace patina::gltf {

namespace {

using SaxJson = nlohmann::json;

// What a JSON value is, as far as the rules care; `text` shows it in a message.
struct Found {
    enum Kind { Null, Boolean, Negative, Unsigned, Float, String, Object, Array } kind;
    std::string text;
    double number = 0.0;
};

std::string expected(const JsonRule& rule) {
    switch (rule.kind) {
    case JsonKind::Object: return "an object";
    case JsonKind::Array: return "an array";
    case JsonKind::String: return "a string";
    case JsonKind::Number: return "a number";
    case JsonKind::Boolean: return "true or false";
    case JsonKind::Integer: return "a whole number";
    case JsonKind::Unsigned: return "a whole number of at least 0";
    case JsonKind::Index: return std::string("the index of a ") + rule.noun;
    }
    return "";
}

// A float that holds a whole number passes where an integer is asked for (2.0 for 2).
bool fits(const JsonRule& rule, const Found& found) {
    const bool whole = found.kind == Found::Negative || found.kind == Found::Unsigned ||
                       (found.kind == Found::Float && found.number == std::floor(found.number));
    const bool notNegative = whole && found.number >= 0.0;
    switch (rule.kind) {
    case JsonKind::Object: return found.kind == Found::Object;
    case JsonKind::Array: return found.kind == Found::Array;
    case JsonKind::String: return found.kind == Found::String;
    case JsonKind::Number: return found.kind == Found::Negative || found.kind == Found::Unsigned || found.kind == Found::Float;
    case JsonKind::Boolean: return found.kind == Found::Boolean;
    case JsonKind::Integer: return whole;
    case JsonKind::Unsigned:
    case JsonKind::Index: return notNegative;
    }
    return true;
}

// RFC 6901: '~' and '/' in a key.
std::string escaped(const std::string& key) {
    std::string text;
    for (const char c : key) {
        text += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    }
    return text;
}

// Where the parse is, as a JSON pointer for messages and as the pattern gltfJsonRule looks up
// (array indices as "*"), and the check of each value against its rule.
class TypedPath {
public:
    void key(const std::string& key) {
        const Frame& frame = frames_.back();
        pointer_.resize(frame.pointerBase);
        pattern_.resize(frame.patternBase);
        // Appended in steps: GCC 12 warns falsely (-Wrestrict) on "/" + std::string here.
        const std::string step = escaped(key);
        pointer_ += '/';
        pointer_ += step;
        pattern_ += '/';
        pattern_ += step;
    }
    // Before each value: an array's element takes its index. Returns what is wrong, or "".
    std::string check(const Found& found) {
        if (!frames_.empty() && frames_.back().array) {
            Frame& frame = frames_.back();
            pointer_.resize(frame.pointerBase);
            pattern_.resize(frame.patternBase);
            pointer_ += '/';
            pointer_ += std::to_string(frame.index++);
            pattern_ += "/*";
        }
        const JsonRule* rule = this->rule();
        if (!rule || fits(*rule, found)) {
            return "";
        }
        if (rule->kind == JsonKind::Index && found.kind == Found::Negative) {
            return pointer_ + ": " + rule->noun + " " + found.text + " does not exist";
        }
        return pointer_ + ": must be " + expected(*rule) + ", not " + found.text;
    }
    void enter(bool array) { frames_.push_back({array, 0, pointer_.size(), pattern_.size()}); }
    void leave() { frames_.pop_back(); }

private:
    struct Frame {
        bool array;
        size_t index, pointerBase, patternBase;
    };
    static constexpr size_t kDeepestRule = 9;   // segments of the longest pattern in json_rules.cpp

    const JsonRule* rule() const {
        if (frames_.empty() || frames_.size() > kDeepestRule) {
            return nullptr;
        }
        if (const JsonRule* exact = gltfJsonRule(pattern_)) {
            return exact;
        }
        const Frame& frame = frames_.back();
        return frame.array ? nullptr : gltfJsonRule(pattern_.substr(0, frame.patternBase) + "/{}");
    }

    std::vector<Frame> frames_;
    std::string pointer_, pattern_;
};

// Counts as it goes and stops the parse at the first broken rule; no document is built.
class Checker final : public nlohmann::json_sax<SaxJson> {
public:
    explicit Checker(bool glb) : glb_(glb) {}

    bool null() override { return value({Found::Null, "null"}); }
    bool boolean(bool b) override {
        if (inBuffers_ && depth_ == 5 && fallbackKey_ && b) {
            bufferIsFallback_ = true;
        }
        return value({Found::Boolean, b ? "true" : "false"});
    }
    bool number_integer(number_integer_t n) override {
        return value({n < 0 ? Found::Negative : Found::Unsigned, std::to_string(n), double(n)});
    }
    bool number_unsigned(number_unsigned_t n) override {
        return value({Found::Unsigned, std::to_string(n), double(n)});
    }
    bool number_float(number_float_t n, const string_t& text) override { return value({Found::Float, text, n}); }
    bool string(string_t& text) override {
        if (depth_ == 2 && rootKey_ == "extensionsRequired") {   // its array's names
            required_.push_back(text);
        }
        return value({Found::String, "a string"});
    }
    bool binary(binary_t&) override { return value({Found::String, "binary data"}); }

    bool start_object(std::size_t) override {
        if (++objects_ > kMaxJsonObjects) {
            return stop("more than " + std::to_string(kMaxJsonObjects) + " objects");
        }
        if (!enter({Found::Object, "an object"}, false)) {
            return false;
        }
        if (inBuffers_ && depth_ == 3) {
            bufferHasUri_ = bufferIsFallback_ = false;
        }
        return true;
    }
    bool key(string_t& key) override {
        path_.key(key);
        if (depth_ == 1) {
            rootKey_ = key;
        } else if (inBuffers_ && depth_ == 3 && key == "uri") {
            bufferHasUri_ = true;
        } else if (inBuffers_ && depth_ == 4) {
            bufferExtension_ = key;
        } else if (inBuffers_ && depth_ == 5) {
            fallbackKey_ = bufferExtension_ == kMeshopt && key == "fallback";
        }
        return true;
    }
    bool end_object() override {
        if (inBuffers_ && depth_ == 3) {
            // EXT_meshopt_compression's fallback buffer has no data at all: its views are
            // read compressed (gltf/meshopt.h).
            if (glb_ && !bufferHasUri_ && !bufferIsFallback_ && buffer_ > 0) {
                return stop("/buffers/" + std::to_string(buffer_) +
                            ": only buffers[0] may take its data from the GLB's BIN chunk "
                            "(this buffer has no uri)");
            }
            ++buffer_;
        }
        --depth_;
        path_.leave();
        return true;
    }
    bool start_array(std::size_t) override {
        if (!enter({Found::Array, "an array"}, true)) {
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
        path_.leave();
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
    const std::vector<std::string>& required() const { return required_; }

private:
    bool value(const Found& found) {
        if (++values_ > kMaxJsonValues) {
            return stop("more than " + std::to_string(kMaxJsonValues) + " JSON values");
        }
        const std::string problem = path_.check(found);
        return problem.empty() || stop(problem);
    }
    bool enter(const Found& found, bool array) {
        if (!value(found)) {
            return false;
        }
        path_.enter(array);
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
    bool inBuffers_ = false, bufferHasUri_ = false, bufferIsFallback_ = false, fallbackKey_ = false;
    std::string bufferExtension_;   // the key of the extension a buffer's parse is in
    size_t buffer_ = 0;
    TypedPath path_;
    std::string problem_;
    std::vector<std::string> required_;   // /extensionsRequired's names
};

// The file's /asset/version, read past anything else ("" where it has none or the JSON breaks
// first), for a file the rules refused: a glTF 1.0 file breaks them at its first
// dictionary-shaped property ("/accessors: must be an array"), which says nothing of why.
// nlohmann's SAX parser keeps its nesting on a heap stack, so a deep file costs no call stack.
class VersionFinder final : public nlohmann::json_sax<SaxJson> {
public:
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool string(string_t& text) override {
        if (inAsset_ && depth_ == 2 && key_ == "version") {
            version_ = text;
            return false;   // found: the rest is not read
        }
        return true;
    }
    bool start_object(std::size_t) override { return enter(); }
    bool start_array(std::size_t) override { return enter(); }
    bool end_object() override { return leave(); }
    bool end_array() override { return leave(); }
    bool key(string_t& key) override {
        key_ = key;
        if (depth_ == 1) {
            inAsset_ = key == "asset";
        }
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
    const std::string& version() const { return version_; }

private:
    bool enter() { return ++depth_ <= kMaxJsonDepth; }
    bool leave() {
        --depth_;
        return true;
    }
    size_t depth_ = 0;
    bool inAsset_ = false;
    std::string key_, version_;
};

// A refused file that says it is not glTF 2 is told so, with what to do about it.
std::string whyRefused(std::string_view json, const std::string& problem) {
    VersionFinder finder;
    SaxJson::sax_parse(json.begin(), json.end(), &finder);
    const std::string& version = finder.version();
    if (!version.empty() && version.rfind("2.", 0) != 0) {
        return "a glTF " + version + " file (asset.version \"" + version +
               "\"); Patina reads glTF 2.0 only: convert it to 2.0 first (gltf-pipeline, on npm, "
               "converts 1.0 files)";
    }
    return problem.empty() ? "invalid JSON" : problem;
}

}  // namespace

std::vector<std::string> checkGltfJson(std::string_view json, bool glb, const std::string& source) {
    Checker checker(glb);
    if (!SaxJson::sax_parse(json.begin(), json.end(), &checker)) {
        throw InputError(source + ": " + whyRefused(json, checker.problem()));
    }
    return checker.required();
}

}  // namespace patina::gltf
