#pragma once
/// @file Water in the joints (docs/formulation.md, "Water"): the pore pressure of a phreatic
/// surface and of prescribed pressure lines, and the wet faces of the blocks it pushes on. The
/// blocks are impermeable; water fills every joint (every interface but the continuum ones),
/// the supports and the outline, on both faces of a joint. The springs carry the effective
/// stress, so the pressure enters as loads alone.
#include <span>
#include <vector>

#include <bimrock/geometry/vec2.hpp>
#include <bimrock/model/case_spec.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

/// The height [m] of a phreatic surface (at least one point, x increasing) above x: linear
/// between its points, level beyond its ends.
double phreatic_height(std::span<const Vec2> surface, double x);

/// The hydrostatic pressure [Pa] at p below a phreatic surface: unit_weight * (h(x) - y), 0
/// above it. h is linear between the surface's points (x increasing) and level beyond its ends.
double phreatic_pressure(std::span<const Vec2> surface, double unit_weight, const Vec2& p);

/// The wet faces of the model's blocks under `water`, cut into pieces on which the pressure is
/// linear (at the surface's points, where it crosses a face, at the ends of pressure lines), so
/// that a two-point Gauss rule integrates the load exactly. A pressure line replaces the
/// phreatic pressure on the faces it lies on. Throws InputError for a pressure line that lies on
/// no wet face.
std::vector<PressureFace> water_faces(const Model& model, const WaterSpec& water);

}  // namespace bimrock
