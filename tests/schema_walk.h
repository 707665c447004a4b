#pragma once
// Reads Patina's JSON Schemas (docs/schema/) just far enough to drive the loaders from them:
// resolves $ref, builds a document from the schema's defaults and lists probes, values just
// inside and just outside each rule. It understands only the keywords those schemas use and
// throws on any other, so a schema cannot state a rule that no test checks.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scene/json_value.h"

namespace patina::test {

class SchemaSet {
public:
    // Loads every *.schema.json in `folder`; $ref names files relative to it.
    explicit SchemaSet(const std::filesystem::path& folder);

    // A schema with its $ref followed and the keywords beside the $ref laid over it, and the
    // file its own $refs are relative to.
    struct Node {
        Json schema;
        std::string file;
    };
    Node root(const std::string& file) const;
    Node resolve(const Json& schema, const std::string& file) const;

private:
    std::map<std::string, Json> documents_;
};

// A document that satisfies the schema: every property, each at its default; an array of
// objects holds one object of each oneOf variant.
Json instantiate(const SchemaSet& schemas, const SchemaSet::Node& node);

struct Probe {
    std::string description;
    Json document;             // `full` with one change
    bool accepted;             // what the schema says of it
    std::string pointer;       // accepted: the unknown key to be warned about, if any;
                               // refused: where the message must point
    bool sameAsFull = false;   // accepted and must load exactly as `full` does
};

// For every rule of the schema met in `full` (built by instantiate): a value at the limit and
// one just past it, every enum member and one non-member, each required key left out, a wrong
// type, an unknown key; and for every object, a copy without the keys that have defaults. A
// pattern is probed with its examples and strings near them (other case, a letter short or
// over); an anyOf of scalars gets every branch's probes, judged by all its branches.
std::vector<Probe> probes(const SchemaSet& schemas, const SchemaSet::Node& root, const Json& full);

// JSON pointers of object keys in `value` that the schema does not list.
std::vector<std::string> undescribedKeys(const SchemaSet& schemas, const SchemaSet::Node& node,
                                         const Json& value, const std::string& pointer = "");

}  // namespace patina::test
