#pragma once
// The body fit as the commands run it: the model from a file or the built-in one, and the fit
// of a whole sequence with a progress line.
#include <clothtrack/body/BodyFit.h>

#include <string>
#include <vector>

namespace clothtrack::app
{
/// The model read from `path` into `storage`, or the built-in model when `path` is empty.
const BodyModel& bodyModel(const std::string& path, BodyModel& storage);

/// fitBodySequence with a "body-fit" progress line counted in frames.
BodyFitResult fitBodiesWithProgress(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyFitOptions& options = {});
} // namespace clothtrack::app
