// MikkTSpace tangents: Mikkelsen's algorithm as his 2008 thesis ("Simulation of wrinkled
// surfaces revisited") and the reference implementation's documentation describe it, written
// here from those descriptions. "Thesis:" below names the step of the method a function
// follows, by what it does: no copy of the thesis was at hand to check section numbers.
#include "geometry/tangents.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
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
    glm::vec3 tangent{0.0f};   // unit dP/ds (= dP/du); zero: no UV gradient or no area
    float sign = 1.0f;         // -1: the face's UVs wind against its corners (a mirrored face)
};

// Thesis: per-face tangent space, in (s, t) = (u, -v). dP/ds and dP/dt solve e1 = Ps ds1 + Pt dt1 and
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

// Thesis: the vertex tangent space. The face's tangent projected into the vertex's tangent
// plane, weighted by the face's angle at the vertex, measured in that plane too. The angle
// keeps the result the same however a fan is cut into triangles.
Contribution contribution(const Surface& s, const FaceTangent& face, uint32_t corner) {
    const uint32_t start = corner - corner % 3, k = corner % 3, v = s.indices[corner];
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

// Each welded vertex's corners (offsets into indices) in index order: those of welded vertex
// w are corners[offsets[w]] up to corners[offsets[w + 1]].
struct CornerLists {
    std::vector<uint32_t> offsets, corners;
};

// Vertices sorted by key, not corners: six times fewer to sort, then the corners counted out.
CornerLists cornersByVertex(const Surface& s) {
    const std::vector<WeldKey> keys = weldKeys(s);
    std::vector<uint32_t> order(keys.size()), ids(keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
    uint32_t id = 0;
    for (size_t i = 0; i < order.size(); ++i) {
        id += i > 0 && keys[order[i]] != keys[order[i - 1]];
        ids[order[i]] = id;
    }
    CornerLists lists{std::vector<uint32_t>(size_t(id) + 2, 0), std::vector<uint32_t>(3 * s.starts.size())};
    for (uint32_t start : s.starts) {
        for (uint32_t corner = start; corner < start + 3; ++corner) {
            ++lists.offsets[ids[s.indices[corner]] + 1];
        }
    }
    std::partial_sum(lists.offsets.begin(), lists.offsets.end(), lists.offsets.begin());
    std::vector<uint32_t> next(lists.offsets.begin(), lists.offsets.end() - 1);
    for (uint32_t start : s.starts) {
        for (uint32_t corner = start; corner < start + 3; ++corner) {
            lists.corners[next[ids[s.indices[corner]]]++] = corner;
        }
    }
    return lists;
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

// The groups at one welded vertex (tangents.h), appended to `out`: within 90 degrees of the
// seed, the weighted sum has a positive part along it, so it never cancels. `faces` holds
// each triangle's tangent; `groups` is scratch space.
void groupVertex(const Surface& s, const std::vector<FaceTangent>& faces, std::span<const uint32_t> corners,
                 std::vector<Group>& groups, Groups& out) {
    const auto first = uint32_t(out.tangents.size());
    groups.clear();
    for (uint32_t corner : corners) {
        const Contribution c = contribution(s, faces[corner / 3], corner);
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
    const glm::vec3& normal = s.normals[s.indices[corners.front()]];
    for (const Group& group : groups) {
        out.tangents.push_back(groupTangent(group, normal));
    }
}

Groups tangentGroups(const Mesh& mesh, int uvSet) {
    Surface s = surface(mesh, uvSet);
    std::vector<FaceTangent> faces(mesh.indices.size() / 3);
    for (uint32_t start : s.starts) {
        faces[start / 3] = faceTangent(s, start);
    }
    const CornerLists lists = cornersByVertex(s);
    Groups groups{{}, std::vector<uint32_t>(mesh.indices.size(), kNoGroup), {}};
    std::vector<Group> scratch;
    for (size_t w = 0; w + 1 < lists.offsets.size(); ++w) {
        const uint32_t begin = lists.offsets[w], end = lists.offsets[w + 1];
        if (begin < end) {   // else a vertex on no triangle kept
            groupVertex(s, faces, std::span(lists.corners).subspan(begin, end - begin), scratch, groups);
        }
    }
    groups.normals = std::move(s.normals);
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
    copy(mesh.colors);
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
