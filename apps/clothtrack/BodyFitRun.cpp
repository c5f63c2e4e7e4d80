#include "BodyFitRun.h"

#include "Progress.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"

namespace clothtrack::app
{
const BodyModel& bodyModel(const std::string& path, BodyModel& storage)
{
  if (path.empty()) return builtinBodyModel();
  storage = readBodyModel(path);
  return storage;
}

BodyFitResult fitBodiesWithProgress(const BodyModel& model,
                                    const std::vector<const TriangleMesh*>& frames,
                                    const BodyFitOptions& options)
{
  // The fit reports a fraction of its work (every frame twice, plus the shape): shown in frames.
  const int n = static_cast<int>(frames.size());
  Progress progress("body-fit", n);
  BodyFitResult result = fitBodySequence(model, frames, options,
                                         [&](double done)
                                         {
                                           progress.step(static_cast<int>(n * done));
                                           return true;
                                         });
  progress.finish();
  return result;
}
} // namespace clothtrack::app
