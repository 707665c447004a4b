#include "geometry/hidden_faces.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace patina {

namespace {

// One id per distinct position. A UV sphere's seam and poles, and a glTF mesh's hard edges,
// repeat a position with other normals; the surface is still closed there. An open-addressed
// hash table: a million triangles' vertices in milliseconds, where a sort took a tenth of a
// second.
std::vector<uint32_t> weldedIds(const std::vector<glm::vec3>& positions) {
    // -0 as +0: equal, but other bits.
    auto bits = [&](size_t v) {
        const glm::vec3& p = positions[v];
        auto word = [](float x) { return std::bit_cast<uint32_t>(x == 0.0f ? 0.0f : x); };
        return std::array<uint32_t, 3>{word(p.x), word(p.y), word(p.z)};
    };
    const size_t capacity = std::bit_ceil(std::max<size_t>(2 * positions.size(), 16));
    constexpr uint32_t kEmpty = ~0u;
    std::vector<uint32_t> slots(capacity, kEmpty);   // the first vertex at each position
    std::vector<uint32_t> ids(positions.size());
    uint32_t next = 0;
    for (size_t v = 0; v < positions.size(); ++v) {
        const std::array<uint32_t, 3> key = bits(v);
        uint64_t hash = (uint64_t(key[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(key[1]) * 0xC2B2AE3D27D4EB4Full) ^
                        (uint64_t(key[2]) * 0x165667B19E3779F9ull);
        hash ^= hash >> 29;
        for (size_t slot = hash & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
            if (slots[slot] == kEmpty) {
                slots[slot] = uint32_t(v);
                ids[v] = next++;
                break;
            }
            if (bits(slots[slot]) == key) {
                ids[v] = ids[slots[slot]];
                break;
            }
        }
    }
    return ids;
}

// Union-find: which triangles reach one another across closed edges.
struct Parts {
    std::vector<uint32_t> parent;
    explicit Parts(size_t count) : parent(count) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t root(uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    }
    void join(uint32_t a, uint32_t b) { parent[root(a)] = root(b); }
};

using Triangle = std::array<uint32_t, 3>;

// Which ways a mesh's edges fold, seen from the side its triangles wind counter-clockwise on.
struct Folds {
    bool towards = false;   // the neighbour rises in front of a triangle's plane (concave)
    bool away = false;      // it falls behind it (convex)
};

// Where triangle b's corner off the edge it shares with `a` lies against a's plane. Within 8
// float roundings of the corners' coordinates counts as flat: a UV sphere's quads are planar,
// and the rounding of their corners gives the diagonals either sign.
void addFold(const std::vector<glm::vec3>& at, const Triangle& a, const Triangle& b, uint32_t v, uint32_t w,
             Folds& folds) {
    const uint32_t corner = b[0] != v && b[0] != w ? b[0] : b[1] != v && b[1] != w ? b[1] : b[2];
    const glm::dvec3 p0(at[a[0]]), p1(at[a[1]]), p2(at[a[2]]), q(at[corner]);
    const glm::dvec3 normal = glm::cross(p1 - p0, p2 - p0);
    const double height = glm::dot(normal, q - p0);
    auto largest = [](const glm::dvec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); };
    const double rounding = 0x1p-24 * std::max({largest(p0), largest(p1), largest(p2), largest(q)});
    if (std::abs(height) > 8.0 * rounding * glm::length(normal)) {
        (height > 0.0 ? folds.towards : folds.away) = true;
    }
}

// Every edge of `triangles` exactly twice, once each way; the two triangles of each edge are
// joined in `parts`, and the way they fold is added to `folds`. Parts are edge-connected, not
// vertex-connected: two closed surfaces touching at a corner, or a two-sided fin hung off one,
// are parts of their own. The edges are bucketed by their lower end (a counting sort,
// linear), so only each vertex's few edges are sorted.
bool closedAndConsistent(const std::vector<Triangle>& triangles, const std::vector<glm::vec3>& at, Parts& parts,
                         Folds& folds) {
    const size_t vertices = at.size();
    std::vector<size_t> start(vertices + 1, 0);
    for (const Triangle& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
        }
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    // Each edge as its higher end (31 bits), bit 32 set when it runs from the higher end down,
    // and its triangle (32 bits): sorted, the two triangles on a closed edge come out side by
    // side, forward first.
    std::vector<uint64_t> far(start.back());
    std::vector<size_t> filled(start.begin(), start.end() - 1);
    for (size_t i = 0; i < triangles.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = triangles[i][k], b = triangles[i][(k + 1) % 3];
            far[filled[std::min(a, b)]++] = (uint64_t(std::max(a, b)) << 33) | (uint64_t(a > b) << 32) | i;
        }
    }
    for (size_t v = 0; v < vertices; ++v) {
        const auto first = far.begin() + std::ptrdiff_t(start[v]), last = far.begin() + std::ptrdiff_t(start[v + 1]);
        std::sort(first, last);
        for (auto e = first; e != last; e += 2) {
            const bool pair = e + 1 != last && (*e >> 32) == (e[1] >> 32) - 1 && ((*e >> 32) & 1u) == 0;
            const bool third = pair && e + 2 != last && (e[2] >> 33) == (*e >> 33);
            if (!pair || third) {
                return false;
            }
            parts.join(uint32_t(*e), uint32_t(e[1]));
            addFold(at, triangles[uint32_t(*e)], triangles[uint32_t(e[1])], uint32_t(v), uint32_t(*e >> 33), folds);
        }
    }
    return true;
}

}  // namespace

FaceCulling faceCulling(const Mesh& mesh) {
    const std::vector<glm::vec3>& positions = mesh.positions;
    // Vertex ids take 31 bits in closedAndConsistent, triangles 32; NaN is not equal to itself.
    if (positions.size() >= (size_t(1) << 31) || mesh.indices.size() % 3 != 0 ||
        mesh.indices.size() / 3 >= (size_t(1) << 32) ||
        !std::all_of(positions.begin(), positions.end(), [](const glm::vec3& p) {
            return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        })) {
        return {};
    }
    const std::vector<uint32_t> ids = weldedIds(positions);
    std::vector<Triangle> triangles;   // welded, without the degenerate ones
    triangles.reserve(mesh.indices.size() / 3);
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        if (std::max({mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]}) >= positions.size()) {
            return {};
        }
        const uint32_t a = ids[mesh.indices[i]], b = ids[mesh.indices[i + 1]], c = ids[mesh.indices[i + 2]];
        if (a == b || b == c || c == a) {
            continue;
        }
        triangles.push_back({a, b, c});
    }
    const std::vector<glm::vec3> welded = [&] {
        std::vector<glm::vec3> p(positions.size());
        for (size_t v = 0; v < positions.size(); ++v) {
            p[ids[v]] = positions[v];
        }
        return p;
    }();
    Parts parts(triangles.size());
    Folds folds;
    if (triangles.empty() || !closedAndConsistent(triangles, welded, parts, folds)) {
        return {};
    }
    // Each part's signed volume (the divergence theorem over its triangles, times 6), about
    // its own first corner so that far-off parts lose no precision, and its box.
    struct Part {
        glm::dvec3 origin{0.0}, low{HUGE_VAL}, high{-HUGE_VAL};
        double volume = 0.0;
    };
    std::vector<Part> volumes;
    std::vector<uint32_t> partOf(triangles.size(), ~0u);   // by root
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto& [a, b, c] = triangles[i];
        const glm::dvec3 p0(welded[a]), p1(welded[b]), p2(welded[c]);
        uint32_t& index = partOf[parts.root(uint32_t(i))];
        if (index == ~0u) {
            index = uint32_t(volumes.size());
            volumes.push_back({p0});
        }
        Part& part = volumes[index];
        part.volume += glm::dot(p0 - part.origin, glm::cross(p1 - part.origin, p2 - part.origin));
        part.low = glm::min(part.low, glm::min(p0, glm::min(p1, p2)));
        part.high = glm::max(part.high, glm::max(p0, glm::max(p1, p2)));
    }
    int outward = 0, inward = 0;
    for (const Part& part : volumes) {
        // A closed part that encloses next to nothing (two sides of one sheet) shows either
        // side; rounding alone would give it a sign.
        const double size = glm::length(part.high - part.low);
        if (std::abs(part.volume) <= 1e-6 * size * size * size) {
            return {};
        }
        ++(part.volume > 0.0 ? outward : inward);
    }
    if (inward != 0 && outward != 0) {
        return {};
    }
    FaceCulling culling;
    culling.hidden = inward == 0 ? HiddenFaces::Back : HiddenFaces::Front;
    // Wound inward, the visible side is the other one: its "towards" is our "away".
    culling.convex = volumes.size() == 1 && !(inward == 0 ? folds.towards : folds.away);
    return culling;
}

HiddenFaces hiddenFaces(const Mesh& mesh) {
    return faceCulling(mesh).hidden;
}

}  // namespace patina
