#pragma once
// Which faces of a mesh no eye outside it can see, so a renderer may skip them: the same image
// for a fraction of the fragments.
#include "geometry/mesh.h"

namespace patina {

enum class HiddenFaces {
    None,    // every face may be seen: the mesh is open, non-manifold, flat or mixed
    Back,    // clockwise on screen (GL's back faces): a closed mesh wound outward
    Front,   // counter-clockwise on screen: a closed mesh wound inward
};

// Back (or Front) when, with vertices at equal positions taken as one, every edge joins
// exactly two triangles that run it in opposite directions (closed, consistently wound; a
// triangle with two equal corners covers nothing and is left out), and every part (triangles
// that reach one another across edges; a shared corner does not join) winds the same way
// round a volume that is not zero. A ray from an eye outside such a mesh
// enters it before it can leave, so it meets a face wound towards the eye first and the
// other side is always behind. Assumes the parts do not pass through themselves.
HiddenFaces hiddenFaces(const Mesh& mesh);

struct FaceCulling {
    HiddenFaces hidden = HiddenFaces::None;
    // One part that is convex: every edge folds away from the visible side or lies flat
    // (within 8 float roundings of its corners). With the hidden side culled, no two faces
    // then cover one sample, and the depth test decides nothing.
    bool convex = false;
};
// hiddenFaces, and whether the mesh is convex, in one pass.
FaceCulling faceCulling(const Mesh& mesh);

}  // namespace patina
