#pragma once
// Point-cloud frames made into meshes, for 'reconstruct' and for 'align' given clouds:
//   FOLDER/frames/frame_NNNN.obj   the reconstructed surface of cloud NNNN (metres, Y up)
//   FOLDER/reconstruction.json     per frame: points kept, topology, fit and doubts
#include "Options.h"

#include "ctMeshConversion.h"

#include <clothtrack/reconstruction/SurfaceReconstruction.h>

#include <string>
#include <vector>

namespace clothtrack::app
{
struct ReconstructSettings
{
  ReconstructionOptions options;
  FrameConventions conventions;
  bool skipBadFrames = false; ///< leave out a cloud that cannot be reconstructed, with a warning
};

/// Reconstructs every cloud in order, with a progress line, and returns the mesh file of each
/// (frame_NNNN numbered from `firstNumber`; "" for a cloud skipped with skipBadFrames). A frame
/// whose mesh exists, newer than its cloud and made with the same options (as reconstruction.json
/// records them), is not reconstructed again.
std::vector<std::string> reconstructSequence(const std::vector<std::string>& clouds,
                                             const std::string& folder,
                                             const ReconstructSettings& settings,
                                             long firstNumber = 0);

/// Adds the reconstruction options (--voxel, --depth, --crop, --outlier-*) to `options`.
void addReconstructionOptions(po::options_description& options, ReconstructionOptions& values);
} // namespace clothtrack::app
