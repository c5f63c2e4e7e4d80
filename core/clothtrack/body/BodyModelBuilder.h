#pragma once
// Learns a BodyModel from a rest-pose template mesh of the mean body and its skeleton:
//  1. skinning weights: each vertex starts on its nearest bone (distance relative to the bone's
//     typical radius) and the one-hot weights are diffused along the surface, so that they blend
//     smoothly across joints and never leak between limbs that are close in space only;
//  2. a population of bodies: sampled BodyParameters turn into per-bone length and girth
//     transforms, blended with the skinning weights (joints follow their bones);
//  3. PCA of the population (vertices and joints together): components scaled by their standard
//     deviation, so that beta is in standard deviations;
//  4. the 40 oriented anatomical landmarks, found on the template by anatomical rules.
#include "BodyModel.h"
#include "ProceduralBody.h"

namespace clothtrack
{
struct BodyModelBuildOptions
{
  int populationSize = 300;
  int numComponents = 16;
  unsigned seed = 20160925;
  /// Surface diffusion steps for the skinning weights (blend width ~ sqrt(steps) edge lengths).
  int weightSmoothingSteps = 40;
  BodySpread spread; ///< of the population's proportions
};

/// Skinning weights (n x NumJoints, at most 4 non-zero per row, rows summing to 1).
Eigen::MatrixXd computeSkinningWeights(const TriangleMesh& mesh, const SkeletonGeometry& skeleton,
                                       double stature, int smoothingSteps);

/// The body of parameters `params`, deformed from the template (rest pose): vertices and joints.
void deformTemplate(const TriangleMesh& mesh, const SkeletonGeometry& skeleton,
                    const Eigen::MatrixXd& weights, const BodyParameters& params, Points& vertices,
                    Points& joints);

/// The 40 oriented landmarks of the template.
std::vector<OrientedLandmark> findLandmarks(const TriangleMesh& mesh,
                                            const SkeletonGeometry& skeleton, double stature);

/// PCA of a population (one body per row: 3n vertex then 3J joint coordinates). Fills the
/// model's mean mesh vertices, joints, bases (one standard deviation per component) and
/// explained variance; `faces` become the mesh's faces.
void learnShapeSpace(Eigen::MatrixXd population, const Triangles& faces, int numComponents,
                     BodyModel& model);

BodyModel buildBodyModel(const TriangleMesh& templateMesh, const SkeletonGeometry& skeleton,
                         double stature, const BodyModelBuildOptions& options = {});
} // namespace clothtrack
