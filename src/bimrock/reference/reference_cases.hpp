#pragma once
/// @file Generated cases of any size, for benchmarks (`bimrock bench`, bench/) and scaling
/// studies. Units SI. The rock and joints are those of the paper's example 1.
#include <bimrock/model/case_spec.hpp>

namespace bimrock {

/// A square brick-pattern mass of about n_blocks blocks of 0.2 m x 0.2 m (rows staggered) on a
/// fixed base, under gravity: an elastic analysis (loads, no stages).
CaseSpec brick_mass_case(int n_blocks);

/// A jointed wall pushed sideways to collapse: bricks 0.4 m x 0.2 m in staggered rows, about
/// n_blocks of them, the wall four times as wide as high, on a fixed base, sides free; joints
/// with cohesion 50 kPa, friction 35 deg, associated flow, tensile strength 50 kPa. Stage 1:
/// gravity. Stage 2: a uniform shear traction on the top edge raised to `shear` [Pa] in
/// `increments` equal steps. The top row slides first, at the closed form of wall_collapse_shear().
CaseSpec wall_case(int n_blocks, int increments, double shear);

/// The shear traction at which the top row of wall_case() slides on its bed joint:
/// tau W = c W + (unit weight x row height x W) tan(phi).
double wall_collapse_shear();

/// The flow rule of a generated case's joints: associated (dilation = friction), or
/// non-associated without dilation (the joint most rock masses and masonry have).
enum class JointFlow { associated, no_dilation };

/// A bridge abutment near the crest of a jointed rock cliff, pushed to collapse: square 0.2 m
/// blocks in staggered rows (bed joints continuous), about n_blocks of them, the mass twice as
/// wide as deep (at least 8 m), fixed base, roller on the left side, the right side a free
/// cliff face; joints with cohesion 50 kPa, friction 35 deg, tensile strength 50 kPa, and
/// associated flow or none of dilation (`flow`). Stage 1: gravity. Stage 2: the abutment's thrust
/// on a 2 m strip of the top ending 2 m from the cliff, a shear `shear` [Pa] towards the cliff with
/// half as much pressure, raised in `increments` steps. The strip does not grow with the model: the
/// plastic zone stays local in a large mass, as in most engineering models. Monitor "abutment" at
/// the strip's outer end.
CaseSpec abutment_case(int n_blocks, int increments, double shear,
                       JointFlow flow = JointFlow::associated);

/// The shear of abutment_case() at which the top row between the strip's inner end and the
/// cliff slides out on its bed joint (limit equilibrium of that slab, its inner vertical joint
/// torn in tension).
double abutment_collapse_shear();

}  // namespace bimrock
