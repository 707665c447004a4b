#include "schema_walk.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <stdexcept>

namespace patina::test {

namespace {
using Pointer = Json::json_pointer;

const std::set<std::string> kKnownKeywords = {
    "$schema", "title", "description", "$comment", "$ref", "$defs", "type", "properties",
    "required", "dependentRequired", "items", "minItems", "maxItems", "minimum", "maximum",
    "const", "enum", "oneOf", "anyOf", "not", "default", "pattern", "examples"};

void checkKeywords(const Json& schema) {
    for (auto it = schema.begin(); it != schema.end(); ++it) {
        if (!kKnownKeywords.count(it.key())) {
            throw std::runtime_error("schema keyword '" + it.key() +
                                     "' is not checked by tests/schema_walk.cpp");
        }
    }
    if (schema.contains("not") && (schema["not"].size() != 1 || !schema["not"].contains("const"))) {
        throw std::runtime_error("only \"not\": {\"const\": ...} is checked");
    }
    if (schema.contains("pattern") && schema.value("type", "") != "string") {
        throw std::runtime_error("a pattern is checked only beside \"type\": \"string\"");
    }
}

std::string typeOf(const SchemaSet::Node& node) {
    return node.schema.value("type", "");
}

Json with(Json document, const Pointer& at, const Json& value) {
    document[at] = value;
    return document;
}

Json without(Json document, const Pointer& at) {
    document[at.parent_pointer()].erase(at.back());
    return document;
}

Json repeated(const Json& element, size_t count) {
    Json array = Json::array();
    for (size_t i = 0; i < count; ++i) {
        array.push_back(element);
    }
    return array;
}

// Another value of the same type as `value`.
Json otherThan(const Json& value) {
    if (value.is_string()) {
        return value.get<std::string>() + "-other";
    }
    if (value.is_number()) {
        return value.get<double>() + 1.0;
    }
    return "other";
}

// JSON Schema's patterns are ECMAScript regular expressions, not anchored.
bool matchesPattern(const Json& schema, const std::string& text) {
    return std::regex_search(text, std::regex(schema["pattern"].get<std::string>()));
}

// Whether `value` satisfies a schema of a scalar, the only kind of anyOf branch checked.
bool accepts(const SchemaSet::Node& node, const Json& value) {
    const Json& schema = node.schema;
    const std::string type = typeOf(node);
    if (type == "object" || type == "array" || schema.contains("oneOf") ||
        schema.contains("anyOf") || schema.contains("not")) {
        throw std::runtime_error("only scalar anyOf branches are checked, not " + schema.dump());
    }
    const bool typeFits = type.empty() || (type == "string" && value.is_string()) ||
                          (type == "boolean" && value.is_boolean()) ||
                          (type == "number" && value.is_number()) ||
                          (type == "integer" && value.is_number() &&
                           std::trunc(value.get<double>()) == value.get<double>());
    const Json members = schema.value("enum", Json::array({value}));
    return typeFits && schema.value("const", value) == value &&
           std::find(members.begin(), members.end(), value) != members.end() &&
           !(value.is_number() && value.get<double>() < schema.value("minimum", -1e300)) &&
           !(value.is_number() && value.get<double>() > schema.value("maximum", 1e300)) &&
           !(value.is_string() && schema.contains("pattern") &&
             !matchesPattern(schema, value.get<std::string>()));
}

// Strings near `example`: in upper, lower and mixed case, one character shorter or longer,
// the part from its last dot on its own and after a folder.
std::vector<std::string> nearMisses(const std::string& example) {
    std::string upper = example, lower = example, mixed = example;
    for (size_t i = 0; i < example.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(example[i]);
        upper[i] = char(std::toupper(c));
        lower[i] = char(std::tolower(c));
        mixed[i] = i % 2 ? lower[i] : upper[i];
    }
    std::vector<std::string> strings = {example, upper, lower, mixed,
                                        example.substr(0, example.size() - 1), example + "x"};
    if (const size_t dot = example.rfind('.'); dot != std::string::npos) {
        strings.push_back(example.substr(dot));
        strings.push_back("folder/" + example.substr(dot));
    }
    return strings;
}

// The oneOf variant `value` is an instance of: the object variant whose "type" property's
// const matches, or the only object variant.
SchemaSet::Node variantFor(const SchemaSet& schemas, const SchemaSet::Node& node, const Json& value) {
    for (const Json& variant : node.schema["oneOf"]) {
        const SchemaSet::Node candidate = schemas.resolve(variant, node.file);
        if (typeOf(candidate) != "object" || !value.is_object()) {
            continue;
        }
        const Json& properties = candidate.schema["properties"];
        if (!properties.contains("type") || !properties["type"].contains("const") ||
            properties["type"]["const"] == value.value("type", Json())) {
            return candidate;
        }
    }
    throw std::runtime_error("no oneOf variant describes " + value.dump());
}

struct Collector {
    const SchemaSet& schemas;
    const Json& full;
    std::vector<Probe>& out;

    // `pointer`: where a refusal must point, or the unknown key an acceptance warns about.
    void add(const std::string& what, const Pointer& at, Json document, bool accepted,
             const std::string& pointer) {
        out.push_back({what + " at " + at.to_string(), std::move(document), accepted, pointer});
    }
    void accept(const std::string& what, const Pointer& at, const Json& value) {
        add(what + " " + value.dump(), at, with(full, at, value), true, "");
    }
    void refuse(const std::string& what, const Pointer& at, const Json& value) {
        add(what + " " + value.dump(), at, with(full, at, value), false, at.to_string());
    }

    void visit(const SchemaSet::Node& node, const Pointer& at) {
        const Json& schema = node.schema;
        checkKeywords(schema);
        const Json& value = full[at];
        if (schema.contains("oneOf")) {
            refuse("none of oneOf:", at, 42);
            visit(variantFor(schemas, node, value), at);
            return;
        }
        if (schema.contains("anyOf")) {
            visitAnyOf(node, at);
            return;
        }
        if (schema.contains("const")) {
            refuse("not the const", at, otherThan(schema["const"]));
        }
        if (schema.contains("enum")) {
            for (const Json& member : schema["enum"]) {
                accept("enum member", at, member);
            }
            refuse("not an enum member", at, otherThan(schema["enum"][0]));
        }
        if (schema.contains("not")) {
            refuse("excluded by not", at, schema["not"]["const"]);
        }
        const std::string type = typeOf(node);
        if (type == "object") {
            visitObject(node, at, value);
        } else if (type == "array") {
            visitArray(node, at, value);
        } else if (type == "number" || type == "integer") {
            visitNumber(schema, at, value, type == "integer");
        } else if (type == "string") {
            refuse("not a string:", at, 42);
            if (schema.contains("pattern")) {
                visitPattern(schema, at);
            }
        } else if (type == "boolean") {
            refuse("not a boolean:", at, "yes");
            accept("boolean", at, !value.get<bool>());
        } else if (!type.empty()) {
            throw std::runtime_error("type '" + type + "' is not checked");
        }
    }

    // Each branch's probes, with the verdict of the whole anyOf: a value one branch refuses
    // may be one another takes.
    void visitAnyOf(const SchemaSet::Node& node, const Pointer& at) {
        std::vector<SchemaSet::Node> branches;
        for (const Json& branch : node.schema["anyOf"]) {
            branches.push_back(schemas.resolve(branch, node.file));
        }
        const size_t first = out.size();
        refuse("none of anyOf:", at, Json::object());   // the branches are scalars
        for (const SchemaSet::Node& branch : branches) {
            visit(branch, at);
        }
        for (size_t i = first; i < out.size(); ++i) {
            const Json& value = out[i].document[at];
            out[i].accepted = std::any_of(branches.begin(), branches.end(),
                                          [&](const SchemaSet::Node& b) { return accepts(b, value); });
            out[i].pointer = out[i].accepted ? "" : at.to_string();
        }
    }

    // A pattern cannot be inverted into strings: its examples, which it must match, and
    // strings near them, each with the pattern's verdict.
    void visitPattern(const Json& schema, const Pointer& at) {
        if (!schema.contains("examples")) {
            throw std::runtime_error("a pattern needs examples to probe it with");
        }
        for (const Json& example : schema["examples"]) {
            if (!matchesPattern(schema, example.get<std::string>())) {
                throw std::runtime_error("the example " + example.dump() + " does not match its pattern");
            }
            for (const std::string& text : nearMisses(example.get<std::string>())) {
                if (matchesPattern(schema, text)) {
                    accept("matches the pattern:", at, text);
                } else {
                    refuse("does not match the pattern:", at, text);
                }
            }
        }
    }

    void visitObject(const SchemaSet::Node& node, const Pointer& at, const Json& value) {
        const Json& schema = node.schema;
        refuse("not an object:", at, 7);
        const Json required = schema.value("required", Json::array());
        for (const Json& key : required) {
            add("without required '" + key.get<std::string>() + "'", at,
                without(full, at / key.get<std::string>()), false, at.to_string());
        }
        const Json dependent = schema.value("dependentRequired", Json::object());
        for (const auto& [key, needs] : dependent.items()) {
            for (const Json& need : needs) {
                if (value.contains(key)) {
                    add("'" + key + "' without '" + need.get<std::string>() + "'", at,
                        without(full, at / need.get<std::string>()), false, at.to_string());
                }
            }
        }
        add("unknown key", at, with(full, at / "zzUnknown", 1), true, (at / "zzUnknown").to_string());
        // The keys with defaults left out must load the same: the defaults are the loader's.
        Json stripped = Json::object();
        for (const auto& [key, property] : schema["properties"].items()) {
            const SchemaSet::Node child = schemas.resolve(property, node.file);
            if (!value.contains(key)) {
                continue;
            }
            const bool isRequired = std::find(required.begin(), required.end(), key) != required.end();
            if (isRequired || !child.schema.contains("default")) {
                stripped[key] = value[key];
            }
            visit(child, at / key);
        }
        out.push_back({"defaults left out at " + at.to_string(), with(full, at, stripped), true, "",
                       true});
    }

    void visitArray(const SchemaSet::Node& node, const Pointer& at, const Json& value) {
        const Json& schema = node.schema;
        refuse("not an array:", at, "text");
        if (schema.contains("maxItems")) {
            const size_t most = schema["maxItems"];
            if (value.size() < most) {   // else `full` itself is the case
                accept("maxItems", at, repeated(value[0], most));
            }
            refuse("over maxItems:", at, repeated(value[0], most + 1));
        }
        if (schema.value("minItems", 0) > 0) {
            refuse("under minItems:", at, repeated(value[0], schema["minItems"].get<size_t>() - 1));
        }
        const SchemaSet::Node items = schemas.resolve(schema["items"], node.file);
        for (size_t i = 0; i < value.size(); ++i) {
            visit(items, at / i);
        }
    }

    void visitNumber(const Json& schema, const Pointer& at, const Json& value, bool integer) {
        refuse("not a number:", at, "text");
        // Just past a bound: a relative step, well above double rounding and below any
        // bound's own precision.
        auto past = [](double bound, double direction) {
            return bound + direction * std::max(std::abs(bound) * 1e-6, 1e-6);
        };
        if (schema.contains("minimum")) {
            const double minimum = schema["minimum"];
            accept("minimum", at, schema["minimum"]);
            refuse("below minimum:", at, past(minimum, -1.0));
        }
        if (schema.contains("maximum")) {
            const double maximum = schema["maximum"];
            accept("maximum", at, schema["maximum"]);
            refuse("above maximum:", at, past(maximum, 1.0));
        }
        if (integer) {
            const double whole = value.get<double>();
            accept("integer written as a float", at, whole);
            refuse("not an integer:", at, whole + 0.5);
        }
    }
};
}  // namespace

SchemaSet::SchemaSet(const std::filesystem::path& folder) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (name.size() > 12 && name.ends_with(".schema.json")) {
            std::ifstream file(entry.path());
            documents_[name] = Json::parse(file);
        }
    }
}

SchemaSet::Node SchemaSet::root(const std::string& file) const {
    return resolve(documents_.at(file), file);
}

SchemaSet::Node SchemaSet::resolve(const Json& schema, const std::string& file) const {
    if (!schema.contains("$ref")) {
        return {schema, file};
    }
    const std::string reference = schema["$ref"];
    const size_t hash = reference.find('#');
    const std::string targetFile = hash == 0 ? file : reference.substr(0, hash);
    Node target = resolve(documents_.at(targetFile)[Pointer(reference.substr(hash + 1))], targetFile);
    for (auto it = schema.begin(); it != schema.end(); ++it) {
        if (it.key() == "required" && target.schema.contains("required")) {
            for (const Json& key : it.value()) {
                target.schema["required"].push_back(key);
            }
        } else if (it.key() != "$ref") {
            target.schema[it.key()] = it.value();
        }
    }
    return target;
}

Json instantiate(const SchemaSet& schemas, const SchemaSet::Node& node) {
    const Json& schema = node.schema;
    if (schema.contains("oneOf")) {
        for (const Json& variant : schema["oneOf"]) {
            const SchemaSet::Node candidate = schemas.resolve(variant, node.file);
            if (typeOf(candidate) == "object") {
                return instantiate(schemas, candidate);
            }
        }
        throw std::runtime_error("oneOf without an object variant");
    }
    if (schema.contains("anyOf") && !schema.contains("default")) {
        return instantiate(schemas, schemas.resolve(schema["anyOf"][0], node.file));
    }
    const std::string type = typeOf(node);
    if (type == "object") {
        Json object = Json::object();
        for (const auto& [key, property] : schema["properties"].items()) {
            object[key] = instantiate(schemas, schemas.resolve(property, node.file));
        }
        return object;
    }
    if (schema.contains("default")) {
        return schema["default"];
    }
    if (schema.contains("const")) {
        return schema["const"];
    }
    if (schema.contains("enum")) {
        return schema["enum"][0];
    }
    if (type == "array") {
        const SchemaSet::Node items = schemas.resolve(schema["items"], node.file);
        Json array = Json::array();
        if (items.schema.contains("oneOf")) {
            for (const Json& variant : items.schema["oneOf"]) {
                array.push_back(instantiate(schemas, schemas.resolve(variant, items.file)));
            }
        } else {
            array = repeated(instantiate(schemas, items), schema.value("minItems", size_t(1)));
        }
        return array;
    }
    if (type == "number" || type == "integer") {
        return std::clamp(0.0, schema.value("minimum", -1e300), schema.value("maximum", 1e300));
    }
    if (type == "boolean") {
        return true;
    }
    return "text";
}

std::vector<Probe> probes(const SchemaSet& schemas, const SchemaSet::Node& root, const Json& full) {
    std::vector<Probe> out;
    Collector{schemas, full, out}.visit(root, Pointer());
    return out;
}

std::vector<std::string> undescribedKeys(const SchemaSet& schemas, const SchemaSet::Node& node,
                                         const Json& value, const std::string& pointer) {
    if (node.schema.contains("oneOf")) {
        return undescribedKeys(schemas, variantFor(schemas, node, value), value, pointer);
    }
    std::vector<std::string> keys;
    const std::string type = typeOf(node);
    if (type == "object" && value.is_object()) {
        const Json& properties = node.schema["properties"];
        for (const auto& [key, child] : value.items()) {
            if (!properties.contains(key)) {
                keys.push_back(pointer + "/" + key);
                continue;
            }
            for (const std::string& inner :
                 undescribedKeys(schemas, schemas.resolve(properties[key], node.file), child,
                                 pointer + "/" + key)) {
                keys.push_back(inner);
            }
        }
    } else if (type == "array" && value.is_array()) {
        const SchemaSet::Node items = schemas.resolve(node.schema["items"], node.file);
        for (size_t i = 0; i < value.size(); ++i) {
            for (const std::string& inner :
                 undescribedKeys(schemas, items, value[i], pointer + "/" + std::to_string(i))) {
                keys.push_back(inner);
            }
        }
    }
    return keys;
}

}  // namespace patina::test
