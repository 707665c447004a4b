#pragma once
// Where a draw item's primitive stands: what its transform does to normals and to the winding
// of its triangles (glTF 2.0 §3.7.2.1; the transform is the node's world matrix, §3.5.3).
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace patina {

// The matrix that takes a primitive's normals into world space under `transform`: normals are
// not points but the planes' directions, so they go through the inverse transpose of the
// linear part. Computed as the cofactor matrix (the inverse transpose times the determinant,
// defined even where the inverse is not), scaled to its largest entry and negated for a mirror,
// so that only its directions and sign are the inverse transpose's. The identity for the
// identity, exactly.
glm::mat3 normalTransform(const glm::mat4& transform);

// Whether `transform` mirrors (its linear part has a negative determinant): the primitive's
// counter-clockwise triangles then wind clockwise seen from their front (glTF 2.0 §3.7.2.1),
// so whoever draws it flips which winding faces front.
bool mirrors(const glm::mat4& transform);

}  // namespace patina
