#include "CorrespondenceStage.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>

namespace clothtrack
{
FrameCorrespondence selfCorrespondence(const TriangleMesh& templateMesh)
{
  FrameCorrespondence c;
  c.vertices.resize(templateMesh.numVertices());
  for (int f = 0; f < templateMesh.numFaces(); ++f)
    for (int corner = 0; corner < 3; ++corner)
    {
      VertexMatch& m = c.vertices[templateMesh.F(f, corner)];
      m.face = f;
      m.bary = Vec3::Unit(corner);
      m.position = templateMesh.vertex(templateMesh.F(f, corner));
      m.patches = 1;
    }
  return c;
}

namespace
{
FrameCorrespondence correspondOne(const TemplatePatches& patches, int k, const FrameAccess& frame,
                                  const LandmarkAccess& landmarks)
{
  const FramePtr mesh = frame(k); // held while its patches grow
  if (!mesh) throw Error("Correspondence: frame " + std::to_string(k) + " is missing.");
  return patches.correspond(*mesh, landmarks(k));
}
} // namespace

void correspondFrames(const TemplatePatches& patches, int templateFrame,
                      const std::vector<int>& which, const FrameAccess& frame,
                      const LandmarkAccess& landmarks,
                      const std::function<void(int, FrameCorrespondence&&)>& done,
                      const StageProgress& progress)
{
  const int count = static_cast<int>(which.size());
  // Frames are independent: each thread takes the next frame as it becomes free (their costs
  // differ), and a frame's patches then run on its thread. Results are handed on in order, and
  // only from the calling thread (chunk 0 of the loop): callbacks such as a Python observer or a
  // GUI's may not run on another.
  std::vector<std::optional<FrameCorrespondence>> ready(count);
  std::mutex mutex;
  std::atomic<int> next{0};
  std::atomic<bool> cancelled{false};
  int delivered = 0;
  auto deliver = [&]
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (delivered < count && ready[delivered] && !cancelled)
    {
      FrameCorrespondence c = std::move(*ready[delivered]);
      ready[delivered].reset();
      lock.unlock();
      done(which[delivered], std::move(c));
      ++delivered;
      if (progress && !progress(static_cast<double>(delivered) / count)) cancelled = true;
      lock.lock();
    }
  };
  parallelFor(
      0, std::min(threadCount(), count),
      [&](int worker)
      {
        for (int m = next++; m < count && !cancelled; m = next++)
        {
          const int k = which[m];
          const auto start = std::chrono::steady_clock::now();
          FrameCorrespondence c = k == templateFrame ? selfCorrespondence(patches.templateMesh())
                                                     : correspondOne(patches, k, frame, landmarks);
          c.seconds =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          {
            const std::lock_guard<std::mutex> lock(mutex);
            ready[m] = std::move(c);
          }
          if (worker == 0) deliver();
        }
      },
      1);
  deliver();
  if (cancelled) throw Error("Patch correspondence: cancelled.");
}
} // namespace clothtrack
