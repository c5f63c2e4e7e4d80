#pragma once
// The template bound to the fitted body: every template vertex takes the skinning weights of the
// body near it at the template frame, or of the body part it hangs from when it is far from the
// body (smoothed over the template, so that cloth spanning two limbs blends them instead of
// tearing), and is then carried to any other frame by the blend of its joints' motions between
// the two fitted poses. The body of each
// frame is fitted on its own, so the template posed this way does not drift along a sequence as
// a chain of neighbour-to-neighbour fits does.
//
// Everything needed is what a fitted body exposes (its posed vertices, skinning weights, joint
// rotations and posed joint positions), not the body model itself.
#include "BodyModel.h"

#include <vector>

namespace clothtrack
{
/// A fitted body's skeleton: its pose (joint rotations) and its posed joint positions.
struct PosedSkeleton
{
  BodyPose pose;
  Points joints = Points::Zero(NumJoints, 3);
};

/// The posed skeleton of shape beta in `pose`.
PosedSkeleton posedSkeleton(const BodyModel& model, const Eigen::VectorXd& beta,
                            const BodyPose& pose);

/// Each joint's rigid motion (3 x 4) from skeleton `from` to skeleton `to`.
std::vector<Eigen::Matrix<double, 3, 4>> jointMotions(const PosedSkeleton& from,
                                                      const PosedSkeleton& to);

/// Changes whenever the skinned template changes for the same inputs, so that fits made from an
/// older one are not resumed beside new ones (2: cloth hanging away from the body binds by part).
inline constexpr int kSkinnedTemplateRevision = 2;

struct SkinnedTemplateOptions
{
  /// Smoothing rounds of the weights over the template's edges (each averages a vertex's
  /// weights with its neighbours').
  int smoothingRounds = 10;
  /// A template vertex takes the weights of the nearest body vertex, unless it lies further than
  /// this (metres) from the body at the template frame: cloth hanging away from the body, a
  /// skirt's hem between the legs. It then takes those of the body part whose bone (the main axis
  /// of the body vertices its joint moves most) is nearest relative to the part's thickness: the
  /// pelvis, rather than whichever leg is nearer (BENCHMARKS.md, "hanging cloth"). Infinity: the
  /// nearest body vertex always.
  double partBindingDistance = 0.08;
};

class SkinnedTemplate
{
public:
  /// Binds `templateMesh` (the template frame's surface) to the body fitted to that frame: its
  /// posed vertices, their skinning weights (vertices x NumJoints) and its skeleton. Throws
  /// Error on an empty template or body, or weights of the wrong size.
  SkinnedTemplate(const TriangleMesh& templateMesh, const Points& bodyVertices,
                  const Eigen::MatrixXd& bodyWeights, const PosedSkeleton& atTemplate,
                  const SkinnedTemplateOptions& options = {});

  /// The template carried to the frame whose fitted body has skeleton `frame`.
  Points posed(const PosedSkeleton& frame) const;

  /// Skinning weights of the template vertices (vertices x NumJoints, rows sum to 1).
  const Eigen::MatrixXd& weights() const { return weights_; }

private:
  Points positions_; ///< the template frame's surface
  Eigen::MatrixXd weights_;
  PosedSkeleton atTemplate_;
};
} // namespace clothtrack
