// MikkTSpace tangents: Mikkelsen's algorithm as his 2008 thesis ("Simulation of wrinkled
// surfaces revisited") and the reference implementation's documentation describe it, written
// here from those descriptions. "Thesis" below names the part of it a step follows.
#include "geometry/tangents.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <tuple>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace patina {

namespace {

constexpr uint32_t kNoGroup = ~0u;

// `v` at length 1, or zero where it has no direction (zero or not finite): what gives no
// direction adds nothing.
glm::vec3 directionOrZero(const glm::vec3& v) {
    const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    return finite && v != glm::vec3(0.0f) ? unitNormal(v) : glm::vec3(0.0f);
}

// `v` without its part along the unit `n`, at length 1 (or zero).
glm::vec3 inPlane(const glm::vec3& v, const glm::vec3& n) {
    return directionOrZero(v - n * glm::dot(n, v));
}

// The triangles as the algorithm reads them.
struct Surface {
    std::span<const glm::vec3> positions;
    std::span<const uint32_t> indices;
    std::vector<uint32_t> starts;      // offsets into indices of the triangles kept
    std::vector<glm::vec3> normals;    // unit, one per position
    std::vector<glm::vec2> st;         // (u, -v) per position, or none
};

// Offsets of the triangles whose corners all index a position: the others are left out.
std::vector<uint32_t> triangleStarts(const Mesh& mesh) {
    std::vector<uint32_t> starts;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        if (std::max({mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]}) < mesh.positions.size()) {
            starts.push_back(uint32_t(i));
        }
    }
    return starts;
}

Surface surface(const Mesh& mesh, int uvSet) {
    Surface s{mesh.positions, mesh.indices, triangleStarts(mesh), mesh.normals, {}};
    if (s.normals.size() != mesh.positions.size()) {
        std::vector<uint32_t> kept;
        for (uint32_t start : s.starts) {
            kept.insert(kept.end(), mesh.indices.begin() + start, mesh.indices.begin() + start + 3);
        }
        s.normals = smoothNormals(mesh.positions, kept);
    }
    for (glm::vec3& n : s.normals) {
        n = unitNormal(n);
    }
    // glTF's v grows down the image; MikkTSpace's t, and a normal map's +Y, up it.
    const std::vector<glm::vec2>* uvs = uvSet == 0 ? &mesh.uv0 : uvSet == 1 ? &mesh.uv1 : nullptr;
    if (uvs != nullptr && uvs->size() == mesh.positions.size()) {
        for (const glm::vec2& uv : *uvs) {
            s.st.emplace_back(uv.x, -uv.y);
        }
    }
    return s;
}

struct FaceTangent {
    glm::vec3 tangent{0.0f};   // unit dP/ds; zero where the face has no UV gradient or no area
    float sign = 1.0f;         // -1: the face's UVs wind against its corners (a mirrored face)
};

// Thesis, per-face tangent space: dP/ds and dP/dt solve e1 = Ps ds1 + Pt dt1 and
// e2 = Ps ds2 + Pt dt2 over the face's edges, so Ps = (dt2 e1 - dt1 e2) / A, where
// A = ds1 dt2 - ds2 dt1 is twice the face's signed area in UV. Only A's sign is used (the
// length is normalised away), so a sliver's tiny A cannot overflow.
FaceTangent faceTangent(const Surface& s, uint32_t start) {
    const uint32_t a = s.indices[start], b = s.indices[start + 1], c = s.indices[start + 2];
    const glm::vec3 e1 = s.positions[b] - s.positions[a], e2 = s.positions[c] - s.positions[a];
    if (s.st.empty() || directionOrZero(glm::cross(e1, e2)) == glm::vec3(0.0f)) {
        return {};
    }
    const glm::vec2 d1 = s.st[b] - s.st[a], d2 = s.st[c] - s.st[a];
    const float area = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(area) > 0.0f)) {   // also NaN
        return {};
    }
    const float sign = area > 0.0f ? 1.0f : -1.0f;
    return {directionOrZero(sign * (d2.y * e1 - d1.y * e2)), sign};
}

// What one corner of a face adds to its vertex's group.
struct Contribution {
    glm::vec3 tangent{0.0f};   // the face's, orthogonal to the vertex's normal, unit
    float weight = 0.0f;       // the face's angle at the vertex; 0: it adds nothing
    float sign = 1.0f;
};

// Thesis, vertex tangent space: the face's tangent projected into the vertex's tangent plane,
// weighted by the face's angle at the vertex, measured in that plane too. The angle keeps the
// result the same however a fan is cut into triangles.
Contribution contribution(const Surface& s, const FaceTangent& face, uint32_t start, uint32_t k) {
    const uint32_t v = s.indices[start + k];
    const glm::vec3& p = s.positions[v];
    const glm::vec3& n = s.normals[v];
    const glm::vec3 tangent = inPlane(face.tangent, n);
    const glm::vec3 next = inPlane(s.positions[s.indices[start + (k + 1) % 3]] - p, n);
    const glm::vec3 previous = inPlane(s.positions[s.indices[start + (k + 2) % 3]] - p, n);
    if (tangent == glm::vec3(0.0f) || next == glm::vec3(0.0f) || previous == glm::vec3(0.0f)) {
        return {};
    }
    return {tangent, std::acos(glm::clamp(glm::dot(next, previous), -1.0f, 1.0f)), face.sign};
}

// Vertices with equal keys are one vertex: position, normal and st, -0 taken as +0.
using WeldKey = std::array<uint32_t, 8>;

std::vector<WeldKey> weldKeys(const Surface& s) {
    auto word = [](float x) { return std::bit_cast<uint32_t>(x == 0.0f ? 0.0f : x); };
    std::vector<WeldKey> keys(s.positions.size());
    for (size_t v = 0; v < keys.size(); ++v) {
        const glm::vec3 &p = s.positions[v], &n = s.normals[v];
        const glm::vec2 st = s.st.empty() ? glm::vec2(0.0f) : s.st[v];
        keys[v] = {word(p.x), word(p.y), word(p.z), word(n.x), word(n.y), word(n.z), word(st.x), word(st.y)};
    }
    return keys;
}

// The kept triangles' corners (offsets into indices), those of one welded vertex side by side,
// each vertex's in index order.
std::vector<uint32_t> cornersByVertex(const Surface& s, const std::vector<WeldKey>& keys) {
    std::vector<uint32_t> corners;
    corners.reserve(3 * s.starts.size());
    for (uint32_t start : s.starts) {
        corners.insert(corners.end(), {start, start + 1, start + 2});
    }
    std::sort(corners.begin(), corners.end(), [&](uint32_t a, uint32_t b) {
        return std::tie(keys[s.indices[a]], a) < std::tie(keys[s.indices[b]], b);
    });
    return corners;
}

struct Groups {
    std::vector<glm::vec4> tangents;    // one per group
    std::vector<uint32_t> cornerGroup;  // one per index; kNoGroup on a triangle left out
    std::vector<glm::vec3> normals;     // the unit normals used
};

struct Group {
    glm::vec3 seed{0.0f}, sum{0.0f};
    float sign = 1.0f;
};

// The group's tangent: the weighted sum, in the tangent plane, unit (thesis: orthonormalised
// against the normal); fallbackTangent where it has none.
glm::vec4 groupTangent(const Group& group, const glm::vec3& n) {
    const glm::vec3 t = inPlane(group.sum, n);
    return {t == glm::vec3(0.0f) ? fallbackTangent(n) : t, group.sign};
}

// The groups at one welded vertex (tangents.h): within 90 degrees of the seed, the weighted
// sum has a positive part along it, so it never cancels.
void groupVertex(std::span<const uint32_t> corners, const std::vector<Contribution>& contributions,
                 const glm::vec3& normal, Groups& out) {
    const auto first = uint32_t(out.tangents.size());
    std::vector<Group> groups;
    for (uint32_t corner : corners) {
        const Contribution& c = contributions[corner];
        if (!(c.weight > 0.0f)) {
            continue;
        }
        auto group = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
            return g.sign == c.sign && glm::dot(g.seed, c.tangent) > 0.0f;
        });
        if (group == groups.end()) {
            group = groups.insert(groups.end(), Group{c.tangent, glm::vec3(0.0f), c.sign});
        }
        group->sum += c.weight * c.tangent;
        out.cornerGroup[corner] = first + uint32_t(group - groups.begin());
    }
    if (groups.empty()) {
        groups.emplace_back();   // only faces without a tangent: the fallback
    }
    for (uint32_t corner : corners) {   // degenerate faces inherit (the reference's rule)
        out.cornerGroup[corner] = out.cornerGroup[corner] == kNoGroup ? first : out.cornerGroup[corner];
    }
    for (const Group& group : groups) {
        out.tangents.push_back(groupTangent(group, normal));
    }
}

Groups tangentGroups(const Mesh& mesh, int uvSet) {
    Surface s = surface(mesh, uvSet);
    std::vector<Contribution> contributions(mesh.indices.size());
    for (uint32_t start : s.starts) {
        const FaceTangent face = faceTangent(s, start);
        for (uint32_t k = 0; k < 3; ++k) {
            contributions[start + k] = contribution(s, face, start, k);
        }
    }
    const std::vector<WeldKey> keys = weldKeys(s);
    const std::vector<uint32_t> corners = cornersByVertex(s, keys);
    Groups groups{{}, std::vector<uint32_t>(mesh.indices.size(), kNoGroup), std::move(s.normals)};
    for (size_t begin = 0, end = 0; begin < corners.size(); begin = end) {
        const uint32_t vertex = mesh.indices[corners[begin]];
        for (end = begin + 1; end < corners.size() && keys[mesh.indices[corners[end]]] == keys[vertex]; ++end) {
        }
        groupVertex(std::span(corners).subspan(begin, end - begin), contributions, groups.normals[vertex], groups);
    }
    return groups;
}

// The group each vertex keeps: its first corner's; kNoGroup where no triangle uses it.
std::vector<uint32_t> keptGroups(const Mesh& mesh, const Groups& groups) {
    std::vector<uint32_t> kept(mesh.positions.size(), kNoGroup);
    for (size_t corner = 0; corner < mesh.indices.size(); ++corner) {
        if (groups.cornerGroup[corner] != kNoGroup && kept[mesh.indices[corner]] == kNoGroup) {
            kept[mesh.indices[corner]] = groups.cornerGroup[corner];
        }
    }
    return kept;
}

std::vector<glm::vec4> vertexTangents(const Groups& groups, const std::vector<uint32_t>& kept) {
    std::vector<glm::vec4> tangents(kept.size());
    for (size_t v = 0; v < kept.size(); ++v) {
        tangents[v] = kept[v] == kNoGroup ? glm::vec4(fallbackTangent(groups.normals[v]), 1.0f)
                                          : groups.tangents[kept[v]];
    }
    return tangents;
}

// A copy of vertex `v` at the end, with `tangent`: every per-vertex attribute comes along.
void appendCopy(Mesh& mesh, uint32_t v, const glm::vec4& tangent) {
    const size_t count = mesh.positions.size();
    auto copy = [&](auto& attribute) {
        if (attribute.size() == count) {
            attribute.push_back(attribute[v]);
        }
    };
    copy(mesh.normals);
    copy(mesh.uv0);
    copy(mesh.uv1);
    mesh.tangents.push_back(tangent);
    mesh.positions.push_back(mesh.positions[v]);
}

}  // namespace

glm::vec3 fallbackTangent(const glm::vec3& normal) {
    const glm::vec3 n = unitNormal(normal);
    const glm::vec3 along = glm::abs(n);
    glm::vec3 axis(0.0f);
    axis[along.x <= along.y && along.x <= along.z ? 0 : along.y <= along.z ? 1 : 2] = 1.0f;
    return glm::normalize(axis - n * glm::dot(n, axis));
}

std::vector<glm::vec4> mikkTSpaceTangents(const Mesh& mesh, int uvSet) {
    const Groups groups = tangentGroups(mesh, uvSet);
    return vertexTangents(groups, keptGroups(mesh, groups));
}

Mesh withTangents(Mesh mesh, int uvSet) {
    const Groups groups = tangentGroups(mesh, uvSet);
    const std::vector<uint32_t> kept = keptGroups(mesh, groups);
    if (mesh.normals.size() != mesh.positions.size()) {
        mesh.normals = groups.normals;
    }
    mesh.tangents = vertexTangents(groups, kept);
    std::unordered_map<uint64_t, uint32_t> copies;   // (vertex, group) -> the copy's index
    for (size_t corner = 0; corner < mesh.indices.size(); ++corner) {
        const uint32_t v = mesh.indices[corner], group = groups.cornerGroup[corner];
        if (group == kNoGroup || group == kept[v]) {
            continue;
        }
        const auto [copy, added] = copies.try_emplace(uint64_t(v) << 32 | group, uint32_t(mesh.positions.size()));
        if (added) {
            appendCopy(mesh, v, groups.tangents[group]);
        }
        mesh.indices[corner] = copy->second;
    }
    return mesh;
}

}  // namespace patina
