#pragma once
// Garments for the synthetic captures: open surface meshes made around a body in rest pose,
// with the skinning weights that carry them along with the body and the rings pinned to it.
#include <clothtrack/body/BodyModel.h>

#include <string>
#include <vector>

namespace clothtrack
{
enum class GarmentType
{
  Dress,    ///< from under the arms, flared below the waist
  Skirt,    ///< from the waist, flared
  Trousers, ///< two loose tubes from the hips to the ankles
  Shirt     ///< a wide torso tube with short sleeves
};

struct GarmentOptions
{
  GarmentType type = GarmentType::Dress;
  /// Hem height as a fraction of stature (dress and skirt).
  double hemHeight = 0.30;
  /// Hem radius relative to the waist radius (dress and skirt).
  double flare = 1.9;
  /// Gap between body and cloth, metres.
  double ease = 0.02;
};

struct Garment
{
  TriangleMesh rest;        ///< rest-pose garment, open surface(s)
  Eigen::MatrixXd weights;  ///< per vertex skinning weights (n x NumJoints)
  std::vector<char> pinned; ///< vertices attached to the body (waist band, shoulders, cuffs)
  /// How strongly each vertex is pulled toward its skinned position (tight fit: 1, loose hem: ~0).
  std::vector<double> follow;
};

/// "dress", "skirt", "trousers", "shirt"; throws Error otherwise.
GarmentType garmentFromName(const std::string& name);

/// Builds a garment around the body of shape beta in rest pose.
Garment makeGarment(const BodyModel& model, const Eigen::VectorXd& beta,
                    const GarmentOptions& options);
} // namespace clothtrack
