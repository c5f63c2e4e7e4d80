#pragma once
// Converts the MakeHuman 1.x CC0 assets (base.obj, default.mhskel, default_weights.mhw and the
// macro targets) into a ClothTrack BodyModel, from the file formats alone:
//  - mesh: the faces of the `body` group of base.obj, triangulated; holes (eyes, ...) closed by
//    a fan around a new centre vertex; decimetres converted to metres, feet on the floor;
//  - skeleton: the 22 ClothTrack joints from the heads of the matching MakeHuman bones (joint
//    positions are means of the helper vertices listed in the skeleton file);
//  - skinning: the MakeHuman bone weights summed into the ClothTrack joint each bone maps to;
//  - shape space: PCA of a population of macro settings (gender, age, muscle, weight, height),
//    each a multilinear blend of the macro targets;
//  - landmarks: the same anatomical rules as the built-in model.
#include "BodyModel.h"

#include <string>

namespace clothtrack
{
struct MakeHumanImportOptions
{
  int populationSize = 200;
  int numComponents = 16;
  unsigned seed = 1;
};

/// `folder` holds base.obj, default.mhskel, default_weights.mhw and targets/macrodetails/.
/// Throws Error naming the file and the problem.
BodyModel importMakeHuman(const std::string& folder, const MakeHumanImportOptions& options = {});
} // namespace clothtrack
