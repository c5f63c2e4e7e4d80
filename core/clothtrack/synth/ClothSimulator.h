#pragma once
// Position-based dynamics for the garments (Mueller et al. 2007): stretch constraints on the
// mesh edges (cloth hardly stretches, it may buckle), weak bending across adjacent triangles,
// gravity and damping, pinned bands that follow the body, a weak pull toward the skinned
// garment (tight parts follow, loose hems swing and lag), and collisions against capsules
// around the posed skeleton and the floor.
#include "Garment.h"

#include <array>
#include <vector>

namespace clothtrack
{
struct ClothOptions
{
  int substeps = 10;
  int iterations = 8;
  double damping = 0.985; ///< velocity kept per substep
  double gravity = 9.81;
  double compression = 0.2; ///< stiffness against compression (1 against stretch)
  double bending = 0.05;
  double collisionMargin = 0.008;
};

class ClothSimulator
{
public:
  ClothSimulator(const BodyModel& model, const Eigen::VectorXd& beta, Garment garment,
                 ClothOptions options = {});

  /// Places the garment on the body in `pose` and lets it settle (no motion).
  void reset(const BodyPose& pose, int settleSteps = 60);
  /// Advances by dt seconds while the body moves to `pose`.
  void step(const BodyPose& pose, double dt);

  const Points& positions() const { return x_; }
  const Garment& garment() const { return garment_; }

private:
  struct Capsule
  {
    int joint;
    double radius;
  };
  void targets(const BodyPose& pose, Points& target, Points& jointsWorld) const;
  void substep(const Points& target, const Points& jointsWorld, double h);

  const BodyModel& model_;
  Eigen::VectorXd beta_;
  Points restJoints_;
  Points boneEnds_; // rest-pose end of each joint's bone (leaves: 0 length)
  Garment garment_;
  ClothOptions options_;
  std::vector<std::array<int, 2>> stretch_, bend_;
  std::vector<double> stretchLength_, bendLength_;
  std::vector<Capsule> capsules_;
  Points x_, previous_;
};
} // namespace clothtrack
