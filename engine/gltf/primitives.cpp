#include "gltf/primitives.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>

#include <glm/geometric.hpp>

#include "files/input_error.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

constexpr AccessorForm kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT};
constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUnsignedByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUnsignedShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;

// Section 3.7.2.1's attribute table: what each attribute Patina reads may be, what
// KHR_mesh_quantization adds to that where the file uses it, and what a message calls its
// elements.
struct Attribute {
    const char* name;
    int type;
    std::vector<AccessorForm> forms;
    std::vector<AccessorForm> quantized;
    const char* elements;
};

// KHR_mesh_quantization's table: a position or a texture coordinate may be any 8- or 16-bit
// integer, normalized or not (the node's transform or KHR_texture_transform scales it back); a
// normal or a tangent a normalized signed one.
const std::vector<AccessorForm> kAnyInteger{{kByte, false},         {kByte, true},          {kUnsignedByte, false},
                                            {kUnsignedByte, true},  {kShort, false},        {kShort, true},
                                            {kUnsignedShort, false}, {kUnsignedShort, true}};
const std::vector<AccessorForm> kSignedNormalized{{kByte, true}, {kShort, true}};

const Attribute kPosition{"POSITION", TINYGLTF_TYPE_VEC3, {kFloat}, kAnyInteger, "positions"};
const Attribute kNormal{"NORMAL", TINYGLTF_TYPE_VEC3, {kFloat}, kSignedNormalized, "normals"};
const Attribute kTangent{"TANGENT", TINYGLTF_TYPE_VEC4, {kFloat}, kSignedNormalized, "tangents"};
const std::vector<AccessorForm> kTexCoordForms{kFloat, {kUnsignedByte, true}, {kUnsignedShort, true}};
const std::vector<AccessorForm> kQuantizedTexCoordForms{{kByte, false}, {kByte, true}, {kUnsignedByte, false},
                                                        {kShort, false}, {kShort, true}, {kUnsignedShort, false}};
// Section 3.7.2.1: COLOR_0 is VEC3 or VEC4, float or normalized unsigned byte or short, with
// KHR_mesh_quantization as without (the extension adds no form for colours).
const std::vector<AccessorForm> kColorForms{kFloat, {kUnsignedByte, true}, {kUnsignedShort, true}};
const Attribute kColors[2] = {{"COLOR_0", TINYGLTF_TYPE_VEC4, kColorForms, {}, "colours"},
                              {"COLOR_0", TINYGLTF_TYPE_VEC3, kColorForms, {}, "colours"}};
const Attribute kTexCoords[2] = {
    {"TEXCOORD_0", TINYGLTF_TYPE_VEC2, kTexCoordForms, kQuantizedTexCoordForms, "texture coordinates"},
    {"TEXCOORD_1", TINYGLTF_TYPE_VEC2, kTexCoordForms, kQuantizedTexCoordForms, "texture coordinates"}};

// Whether the plan's Draco stream holds the attribute `name`.
bool compressed(const PrimitivePlan& plan, const std::string& name) {
    return plan.draco && plan.draco->attributes.count(name);
}

// The forms `attribute` may take in a file that does or does not use KHR_mesh_quantization.
std::vector<AccessorForm> formsOf(const Attribute& attribute, bool quantized) {
    std::vector<AccessorForm> forms = attribute.forms;
    if (quantized) {
        forms.insert(forms.end(), attribute.quantized.begin(), attribute.quantized.end());
    }
    return forms;
}

// The attribute's accessor when the primitive has one, as many elements as positions.
std::optional<CheckedAccessor> planAttribute(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                             const Attribute& attribute, bool quantized, const PrimitivePlan& plan,
                                             const std::string& source) {
    const auto found = primitive.attributes.find(attribute.name);
    if (found == primitive.attributes.end()) {
        return std::nullopt;
    }
    const std::string what = plan.where + "/attributes/" + attribute.name;
    CheckedAccessor accessor = checkAccessor(model, found->second, attribute.type, formsOf(attribute, quantized), what,
                                             source, compressed(plan, attribute.name));
    if (accessor.count != plan.positions.count) {
        fail(source, what + ": " + std::to_string(accessor.count) + " " + attribute.elements + " for " +
                         std::to_string(plan.positions.count) + " positions");
    }
    return accessor;
}

// COLOR_0's accessor, as an RGB one where the file says VEC3, else as RGBA.
std::optional<CheckedAccessor> planColors(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                          bool quantized, const PrimitivePlan& plan, const std::string& source) {
    const auto found = primitive.attributes.find(kColors[0].name);
    const bool rgb = found != primitive.attributes.end() && found->second >= 0 &&
                     size_t(found->second) < model.accessors.size() &&
                     model.accessors[size_t(found->second)].type == TINYGLTF_TYPE_VEC3;
    return planAttribute(model, primitive, kColors[rgb ? 1 : 0], quantized, plan, source);
}

// Every element of a float accessor as a vector of `Vec`, each number finite.
template <typename Vec>
std::vector<Vec> readVectors(const CheckedAccessor& accessor, const std::string& what, const std::string& source) {
    const std::vector<float> numbers = readFloats(accessor);
    constexpr size_t n = size_t(Vec::length());
    std::vector<Vec> vectors(accessor.count);
    for (size_t i = 0; i < vectors.size(); ++i) {
        if (!std::all_of(&numbers[i * n], &numbers[i * n] + n, [](float x) { return std::isfinite(x); })) {
            fail(source, what + ": element " + std::to_string(i) + " is not finite");
        }
        std::memcpy(&vectors[i][0], &numbers[i * n], sizeof(float) * n);
    }
    return vectors;
}

// COLOR_0's elements as linear RGBA: an RGB accessor's alpha is 1.
std::vector<glm::vec4> readColors(const CheckedAccessor& accessor, const std::string& what, const std::string& source) {
    if (accessor.components == 4) {
        return readVectors<glm::vec4>(accessor, what, source);
    }
    std::vector<glm::vec4> colors;
    colors.reserve(accessor.count);
    for (const glm::vec3& rgb : readVectors<glm::vec3>(accessor, what, source)) {
        colors.emplace_back(rgb, 1.0f);
    }
    return colors;
}

// The primitive's corners: its indices, each checked, or 0, 1, 2, ... without them.
std::vector<uint32_t> readCorners(const PrimitivePlan& plan, const std::string& source) {
    const size_t vertices = plan.positions.count;
    if (!plan.indices) {
        std::vector<uint32_t> corners(vertices);
        std::iota(corners.begin(), corners.end(), 0u);
        return corners;
    }
    std::vector<uint32_t> corners = readIntegers(*plan.indices);
    for (size_t i = 0; i < corners.size(); ++i) {
        if (corners[i] >= vertices) {
            fail(source, plan.where + "/indices: element " + std::to_string(i) + " is " + std::to_string(corners[i]) +
                             " but the primitive has " + std::to_string(vertices) + " vertices");
        }
    }
    return corners;
}

// Triangle lists from the corners, in glTF's order for strips and fans (section 3.7.2.1).
std::vector<uint32_t> assembleTriangles(int mode, const std::vector<uint32_t>& c, size_t triangles) {
    std::vector<uint32_t> out(triangles * 3);
    for (size_t t = 0; t < triangles; ++t) {
        uint32_t* triangle = &out[3 * t];
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            triangle[0] = c[3 * t], triangle[1] = c[3 * t + 1], triangle[2] = c[3 * t + 2];
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            triangle[0] = c[t + (t % 2)], triangle[1] = c[t + 1 - (t % 2)], triangle[2] = c[t + 2];
        } else {
            triangle[0] = c[t + 1], triangle[1] = c[t + 2], triangle[2] = c[0];
        }
    }
    return out;
}

// In double: a float cross product of a triangle 1e-20 across underflows, one 1e20 across overflows.
glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    if (!(largest > 0.0) || !std::isfinite(largest)) {
        return glm::vec3(0.0f, 1.0f, 0.0f);   // no area: as smoothNormals does
    }
    return glm::vec3(glm::normalize(n / largest));
}

// A copy of vertex `v` for another normal; its index.
uint32_t copyVertex(Mesh& mesh, uint32_t v, const glm::vec3& normal, const PrimitivePlan& plan,
                    const std::string& source) {
    if (mesh.positions.size() >= kGltfMaxVertices) {
        fail(source, plan.where + ": its flat normals need more than " + std::to_string(kGltfMaxVertices) +
                         " vertices (Patina's limit)");
    }
    mesh.positions.push_back(mesh.positions[v]);
    mesh.normals.push_back(normal);
    for (std::vector<glm::vec2>* uv : {&mesh.uv0, &mesh.uv1}) {
        if (!uv->empty()) {
            uv->push_back((*uv)[v]);
        }
    }
    if (!mesh.colors.empty()) {
        mesh.colors.push_back(mesh.colors[v]);
    }
    return uint32_t(mesh.positions.size() - 1);
}

// Section 3.7.2.1: without normals, each triangle is shaded by its own plane's normal. A vertex
// keeps the normal of the first triangle that uses it; a triangle facing elsewhere gets a copy,
// which the next triangle facing that way reuses: a mesh already split by face (a cube of 24
// vertices) keeps its vertices. Tangents are ignored, as the spec says.
void flatNormals(Mesh& mesh, const PrimitivePlan& plan, const std::string& source) {
    constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    const size_t original = mesh.positions.size();
    mesh.normals.assign(original, glm::vec3(0.0f, 1.0f, 0.0f));   // a vertex on no triangle: +y
    mesh.tangents.clear();
    std::vector<bool> claimed(original, false);
    std::vector<uint32_t> lastCopy(original, kNone);
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        uint32_t* corner = &mesh.indices[t];
        const glm::vec3 n = faceNormal(mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = corner[k];
            if (!claimed[v]) {
                claimed[v] = true;
                mesh.normals[v] = n;
            } else if (mesh.normals[v] != n) {
                if (lastCopy[v] == kNone || mesh.normals[lastCopy[v]] != n) {
                    lastCopy[v] = copyVertex(mesh, v, n, plan, source);
                }
                corner[k] = lastCopy[v];
            }
        }
    }
}

// A Draco primitive's plan with its compressed accessors pointing at the decoded values, which
// `values` holds (a move keeps them where they are); the indices are the decoded corners.
struct Decompressed {
    PrimitivePlan plan;
    DecodedDraco values;
};

// The planned attributes by their glTF names.
std::vector<std::pair<const char*, CheckedAccessor*>> plannedAttributes(PrimitivePlan& plan) {
    std::vector<std::pair<const char*, CheckedAccessor*>> attributes{{"POSITION", &plan.positions}};
    for (auto [name, accessor] : {std::pair{kNormal.name, &plan.normals}, std::pair{kTangent.name, &plan.tangents},
                                  std::pair{kTexCoords[0].name, &plan.texCoords[0]},
                                  std::pair{kTexCoords[1].name, &plan.texCoords[1]},
                                  std::pair{kColors[0].name, &plan.colors}}) {
        if (*accessor) {
            attributes.emplace_back(name, &**accessor);
        }
    }
    return attributes;
}

// Points `accessor` at `bytes`: `count` elements packed as its form says (3.6.2.4: no stride).
void pointAt(CheckedAccessor& accessor, const std::vector<uint8_t>& bytes, size_t count, const std::string& what,
             const std::string& source) {
    if (count != accessor.count) {
        fail(source, what + ": the compressed mesh has " + std::to_string(count) + " where the accessor says " +
                         std::to_string(accessor.count));
    }
    const size_t stride = size_t(accessor.components) * size_t(tinygltf::GetComponentSizeInBytes(accessor.componentType));
    accessor.dense = {bytes.data(), count, stride};
    accessor.sparseIndices = accessor.sparseValues = {};
}

Decompressed decompress(const PrimitivePlan& compressed, const std::string& source) {
    Decompressed out{compressed, {}};
    PrimitivePlan& plan = out.plan;
    plan.draco.reset();
    const std::vector<std::pair<const char*, CheckedAccessor*>> attributes = plannedAttributes(plan);
    std::map<std::string, DracoAttributeForm> forms;
    for (const auto& [name, accessor] : attributes) {
        forms[name] = {accessor->componentType, accessor->components};
    }
    out.values = decodeDraco(*compressed.draco, forms, plan.where, source);
    for (const auto& [name, accessor] : attributes) {
        const auto decoded = out.values.attributes.find(name);
        if (decoded != out.values.attributes.end()) {
            pointAt(*accessor, decoded->second.bytes, decoded->second.count,
                    plan.where + "/attributes/" + name + " (compressed)", source);
        }
    }
    // Draco holds triangles whatever the mode says (the extension allows a strip): the corners
    // are a triangle list.
    if (!plan.indices) {
        plan.indices = CheckedAccessor{};
        plan.indices->count = out.values.corners.size();
        plan.indices->components = 1;
        plan.indices->where = source + ": " + plan.where + "/extensions/" + kDraco;
    }
    plan.indices->componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    plan.indices->normalized = false;
    plan.indices->dense = {reinterpret_cast<const uint8_t*>(out.values.corners.data()), out.values.corners.size(),
                           sizeof(uint32_t)};
    if (out.values.corners.size() != plan.indices->count) {
        fail(source, plan.where + "/indices (compressed): the compressed mesh has " +
                         std::to_string(out.values.corners.size()) + " corners where the accessor says " +
                         std::to_string(plan.indices->count));
    }
    plan.indices->sparseIndices = plan.indices->sparseValues = {};
    plan.mode = TINYGLTF_MODE_TRIANGLES;
    plan.triangles = out.values.corners.size() / 3;
    return out;
}

}  // namespace

std::string whyNotDrawn(const tinygltf::Primitive& primitive, const std::string& where, const std::string& source) {
    if (primitive.mode < TINYGLTF_MODE_POINTS || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
        fail(source, where + "/mode: unknown mode " + std::to_string(primitive.mode));
    }
    if (primitive.mode == TINYGLTF_MODE_POINTS) {
        return "points";
    }
    if (primitive.mode < TINYGLTF_MODE_TRIANGLES) {
        return "lines";
    }
    // Section 3.7.2.1: without positions a primitive SHOULD not be drawn.
    return primitive.attributes.count("POSITION") ? "" : "no POSITION";
}

PrimitivePlan planPrimitive(const tinygltf::Model& model, int mesh, int index, const std::string& source) {
    const tinygltf::Primitive& primitive = model.meshes[size_t(mesh)].primitives[size_t(index)];
    PrimitivePlan plan;
    plan.where = "/meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(index);
    plan.mode = primitive.mode;
    if (primitive.material != -1 && (primitive.material < 0 || size_t(primitive.material) >= model.materials.size())) {
        fail(source, plan.where + "/material: material " + std::to_string(primitive.material) + " does not exist");
    }
    plan.material = primitive.material;
    int indices = primitive.indices;
    if (std::optional<DracoPrimitive> draco = dracoPrimitive(model, primitive, plan.where, source)) {
        plan.draco = std::move(draco->stream);
        indices = indices != -1 ? indices : draco->indices;
    }
    const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                     "KHR_mesh_quantization") != model.extensionsUsed.end();
    plan.positions = checkAccessor(model, primitive.attributes.at("POSITION"), TINYGLTF_TYPE_VEC3,
                                   formsOf(kPosition, quantized), plan.where + "/attributes/POSITION", source,
                                   compressed(plan, "POSITION"));
    plan.normals = planAttribute(model, primitive, kNormal, quantized, plan, source);
    plan.tangents = planAttribute(model, primitive, kTangent, quantized, plan, source);
    for (int set = 0; set < 2; ++set) {
        plan.texCoords[set] = planAttribute(model, primitive, kTexCoords[set], quantized, plan, source);
    }
    plan.colors = planColors(model, primitive, quantized, plan, source);
    if (indices != -1) {
        plan.indices = checkAccessor(model, indices, TINYGLTF_TYPE_SCALAR,
                                     {{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE},
                                      {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                      {TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}},
                                     plan.where + "/indices", source, plan.draco.has_value());
    }
    const size_t corners = plan.indices ? plan.indices->count : plan.positions.count;
    plan.triangles = plan.mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners >= 3 ? corners - 2 : 0;
    return plan;
}

Mesh readPrimitive(const PrimitivePlan& plan, const std::string& source) {
    if (plan.draco) {
        const Decompressed decompressed = decompress(plan, source);
        return readPrimitive(decompressed.plan, source);
    }
    Mesh mesh;
    const std::string attributes = plan.where + "/attributes/";
    mesh.positions = readVectors<glm::vec3>(plan.positions, attributes + "POSITION", source);
    mesh.indices = assembleTriangles(plan.mode, readCorners(plan, source), plan.triangles);
    for (int set = 0; set < 2; ++set) {
        if (plan.texCoords[set]) {
            (set == 0 ? mesh.uv0 : mesh.uv1) =
                readVectors<glm::vec2>(*plan.texCoords[set], attributes + kTexCoords[set].name, source);
        }
    }
    if (plan.colors) {
        mesh.colors = readColors(*plan.colors, attributes + kColors[0].name, source);
    }
    if (!plan.normals) {
        flatNormals(mesh, plan, source);
        return mesh;
    }
    mesh.normals = readVectors<glm::vec3>(*plan.normals, attributes + "NORMAL", source);
    for (glm::vec3& n : mesh.normals) {
        n = unitNormal(n);
    }
    if (plan.tangents) {
        mesh.tangents = readVectors<glm::vec4>(*plan.tangents, attributes + "TANGENT", source);
        for (glm::vec4& t : mesh.tangents) {
            t = glm::vec4(unitNormal(glm::vec3(t)), t.w < 0.0f ? -1.0f : 1.0f);   // w is the handedness, +-1
        }
    }
    return mesh;
}

}  // namespace patina::gltf
