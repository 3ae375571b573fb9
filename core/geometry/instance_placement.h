// Where an instance may be handed to Embree: a transform whose inverse is finite and
// tame (docs/architecture.md, "Singular transforms"), and for a moving instance the
// stretches of the shutter where its interpolated transform stays so. Embree traces a
// ray through the inverse of an instance's transform; a scale at or near zero makes
// that inverse infinite or huge, and Embree aborts on the ray it would produce.
#pragma once

#include "core/math/transform.h"

#include <embree3/rtcore.h>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace inkray {

// An affine transform as Embree's T R S (RTCQuaternionDecomposition): the linear part
// split by Gram-Schmidt into a proper rotation R (a reflection stays in S) and an upper
// triangular S of scales and shears. Embree interpolates a moving instance in this form:
// S and T linearly, R by slerp.
struct Decomposition {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dmat3 upper{1.0};  // S, column-major: upper[column][row]
  glm::dvec3 translation{0.0};
};

Decomposition decompose(const Transform& t);
RTCQuaternionDecomposition embree_decomposition(const Decomposition& d);

// The smallest scale S may have against its largest before the transform counts as
// singular: flatter than this, an object is a sheet with no thickness worth tracing.
inline constexpr double kMinScaleRatio = 1e-6;

// Whether a transform can place an instance: finite, with S's smallest diagonal above
// kMinScaleRatio of its largest. An object whose transform is not placeable at the
// frame is not drawn at that frame.
bool placeable(const Transform& t);

// One stretch [start, end] of the shutter (in Embree's time, [0, 1]) over which a
// moving instance's interpolated transform stays placeable, with its transforms at
// both ends (the second's rotation on the first's side, so the slerp goes the short way).
struct MotionPiece {
  float start = 0.f, end = 1.f;
  RTCQuaternionDecomposition at_start, at_end;
};

// The pieces of the shutter over which an instance moving from `open` to `close` is
// traced: all of it when no scale of S passes through zero, else the stretches either
// side of each instant where one does, less the instants around it where the
// transform is not placeable. Empty when it is nowhere placeable.
std::vector<MotionPiece> motion_pieces(const Transform& open, const Transform& close);

}  // namespace inkray
