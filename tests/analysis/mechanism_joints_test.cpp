// One mode per joint point of a mechanism, against hand-worked relative displacements and
// plastic flows. The block on an incline (tests/support/incline_case.hpp: slope along x,
// downslope +x) gives the yield points of a real model.
#include <gtest/gtest.h>

#include <bimrock/analysis/mechanism_joints.hpp>
#include <bimrock/assembly/yield_points.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

TEST(MechanismJoints, ModesOfRelativeDisplacements) {
  EXPECT_EQ(classify_joint_motion({1.0, 0.0}, 1e-3), JointMotion::opening);
  EXPECT_EQ(classify_joint_motion({0.0, 1.0}, 1e-3), JointMotion::slip_positive);
  EXPECT_EQ(classify_joint_motion({0.0, -1.0}, 1e-3), JointMotion::slip_negative);
  EXPECT_EQ(classify_joint_motion({0.5, 1.0}, 1e-3), JointMotion::slip_positive_opening);
  EXPECT_EQ(classify_joint_motion({0.5, -1.0}, 1e-3), JointMotion::slip_negative_opening);
  // Closing is no opening; below the absolute threshold nothing counts.
  EXPECT_EQ(classify_joint_motion({-0.5, -1.0}, 1e-3), JointMotion::slip_negative);
  EXPECT_EQ(classify_joint_motion({5e-4, -5e-4}, 1e-3), JointMotion::none);
  // A part under 1% of the point's own motion does not count: 0.005 of a slip of 1.
  EXPECT_EQ(classify_joint_motion({0.005, 1.0}, 1e-3), JointMotion::slip_positive);
  EXPECT_EQ(classify_joint_motion({0.02, 1.0}, 1e-3), JointMotion::slip_positive_opening);
}

TEST(MechanismJoints, NamesAsInTheResults) {
  EXPECT_STREQ(joint_motion_name(JointMotion::slip_negative_opening), "slip- with opening");
  EXPECT_STREQ(joint_motion_name(JointMotion::opening), "opening");
  EXPECT_STREQ(joint_motion_name(JointMotion::none), "none");
}

TEST(MechanismJoints, NetPlasticFlowOfAHingeIsOpening) {
  // slip+ = slip- = 1 with opening 0.5, no dilation: (0 + 0 + 0.5, 1 - 1) = (0.5, 0).
  const Eigen::Vector2d hinge = net_plastic_flow({1.0, 1.0, 0.5}, 0.0);
  EXPECT_NEAR(hinge(0), 0.5, 1e-15);
  EXPECT_NEAR(hinge(1), 0.0, 1e-15);
  EXPECT_EQ(classify_joint_motion(hinge, 1e-3), JointMotion::opening);
  // Dilatant slip+ and slip- alike, tan psi = 0.2, no opening mode: (0.4, 0), opening too.
  EXPECT_EQ(classify_joint_motion(net_plastic_flow({1.0, 1.0, 0.0}, 0.2), 1e-3),
            JointMotion::opening);
  // slip+ alone: (tan psi, 1).
  EXPECT_EQ(classify_joint_motion(net_plastic_flow({1.0, 0.0, 0.0}, 0.0), 1e-3),
            JointMotion::slip_positive);
  EXPECT_EQ(classify_joint_motion(net_plastic_flow({1.0, 0.0, 0.0}, 0.1), 1e-3),
            JointMotion::slip_positive_opening);
  EXPECT_EQ(classify_joint_motion(net_plastic_flow({0.3, 1.0, 0.0}, 0.0), 1e-3),
            JointMotion::slip_negative);
}

// The joint points of the block [0, w] x [0, h] on the base, and a collapse whose mechanism
// holds the given mode at each of them.
struct OnIncline {
  Model model;
  std::vector<YieldPoint> points;
  std::vector<int> joint;  // the two points of the joint between the block and the base
};

OnIncline on_incline(double width, double height) {
  testing::Incline in;
  in.width = width;
  in.height = height;
  OnIncline o{build_model(testing::incline_case(in)), {}, {}};
  o.points = make_yield_points(o.model);
  for (std::size_t p = 0; p < o.points.size(); ++p) {
    if (o.points[p].is_interface() && o.points[p].block_j != kGround)
      o.joint.push_back(static_cast<int>(p));
  }
  return o;
}

TEST(MechanismJoints, ABlockSlidingDownslopeSlipsNegatively) {
  // Block 1 translates downslope (+x) over the base at 1 m per unit. The joint's normal n from
  // block i into block j is (0, +1) or (0, -1) and s = (-n_y, n_x); delta_s = s . (v_j - v_i).
  // With i the base: n = (0, 1), s = (-1, 0), v_j - v_i = (1, 0): delta_s = -1. With i the
  // block: n = (0, -1), s = (1, 0), v_j - v_i = (-1, 0): delta_s = -1 again. So slip-.
  OnIncline o = on_incline(2.0, 0.5);
  ASSERT_EQ(o.joint.size(), 2u);
  Collapse c;
  for (int p : o.joint)
    c.mechanism.push_back({p, 1, 1.0});
  c.direction = Eigen::VectorXd::Zero(o.model.n_dofs());
  c.direction(6) = 1.0;
  const std::vector<MechanismJoint> joints = mechanism_joints(o.model, o.points, c, 1.0);
  ASSERT_EQ(joints.size(), 2u);
  for (const MechanismJoint& j : joints) {
    EXPECT_NEAR(j.delta(0), 0.0, 1e-14);
    EXPECT_NEAR(j.delta(1), -1.0, 1e-14);
    EXPECT_EQ(j.motion, JointMotion::slip_negative);
  }
}

TEST(MechanismJoints, AToppledBlockOpensAtItsHeelAndPivotsAtItsToe) {
  // The 1 x 2.5 block turns clockwise (theta = -1) about its toe (1, 0): the heel (0, 0)
  // moves by theta x (heel - toe) = (-theta * 0, theta * (0 - 1)) = (0, 1), straight up off
  // the base: delta_n = 1 (n . (v_j - v_i) is the same for either choice of i), delta_s = 0.
  // The toe does not move: none. Scaled by 2, the relative displacements halve.
  OnIncline o = on_incline(1.0, 2.5);
  ASSERT_EQ(o.joint.size(), 2u);
  Collapse c;
  for (int p : o.joint)
    c.mechanism.push_back({p, kOpeningMode, 1.0});
  c.direction = Eigen::VectorXd::Zero(o.model.n_dofs());
  c.direction.segment<6>(6) << 1.25, 0.5, -1.0, 0, 0, 0;
  const std::vector<MechanismJoint> joints = mechanism_joints(o.model, o.points, c, 2.0);
  ASSERT_EQ(joints.size(), 2u);
  for (const MechanismJoint& j : joints) {
    const Vec2& at = o.points[static_cast<std::size_t>(j.point)].position;
    if (at.x() < 0.5) {  // the heel
      EXPECT_NEAR(j.delta(0), 0.5, 1e-14);
      EXPECT_NEAR(j.delta(1), 0.0, 1e-14);
      EXPECT_EQ(j.motion, JointMotion::opening);
    } else {  // the toe
      EXPECT_NEAR(j.delta.norm(), 0.0, 1e-14);
      EXPECT_EQ(j.motion, JointMotion::none);
    }
  }
}

TEST(MechanismJoints, WithoutADirectionAHingeOfEqualSlipsReadsAsOpening) {
  // Slip+ and slip- of multiplier 1 each and opening 0.5 at one point, the joint without
  // dilation: the net flow is (0.5, 0), opening; one point, listed once.
  OnIncline o = on_incline(2.0, 0.5);
  Collapse c;
  c.mechanism = {{o.joint[0], 0, 1.0}, {o.joint[0], 1, 1.0}, {o.joint[0], kOpeningMode, 0.5}};
  const std::vector<MechanismJoint> joints = mechanism_joints(o.model, o.points, c, 0.0);
  ASSERT_EQ(joints.size(), 1u);
  EXPECT_EQ(joints[0].point, o.joint[0]);
  EXPECT_NEAR(joints[0].delta(0), 0.5, 1e-15);
  EXPECT_EQ(joints[0].motion, JointMotion::opening);
}

}  // namespace
}  // namespace bimrock
