#pragma once
// The HTML report of an aligned sequence, drawn by the clothtrack Python package.
#include <string>
#include <vector>

namespace clothtrack::app
{
/// Runs 'python3 -m clothtrack.report folder' (on a virtual display when there is none);
/// UsageError with the reason when it fails.
void writeReport(const std::string& folder);

/// Runs 'python3 -m clothtrack.movie folder options...': OUT/movie/*.png (and movie.mp4).
void writeMovie(const std::string& folder, const std::vector<std::string>& options);

/// Runs 'python3 -m module folder options...' with the package on PYTHONPATH (the module starts
/// a virtual display when there is none); UsageError when the folder has no metrics.json, when
/// there is neither a display nor Xvfb, or when the module fails.
void runPackageModule(const std::string& module, const std::string& folder,
                      const std::vector<std::string>& options);
} // namespace clothtrack::app
