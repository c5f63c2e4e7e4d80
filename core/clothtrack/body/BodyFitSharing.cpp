#include "BodyFitSharing.h"

#include "BodyFit.h"

#include <clothtrack/base/Bytes.h>
#include <clothtrack/base/Error.h>

#include <cstdint>

namespace clothtrack
{
namespace
{
/// Bumped with any change of the layout below.
constexpr std::uint32_t kLayout = 0x43544232; // "CTB2"

void putFit(ByteWriter& w, const BodyFrameFit& f)
{
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) w.put(f.pose.rotations(j, c));
  for (int c = 0; c < 3; ++c) w.put(f.pose.translation[c]);
  w.put(static_cast<std::int32_t>(f.status));
  w.putText(f.message);
  for (double v : {f.energy, f.medianDistance, f.insideFraction, f.frameDistance, f.previousGap,
                   f.rivalScoreRatio})
    w.put(v);
  w.put(static_cast<std::int32_t>(f.extremitiesDetected));
  w.put(static_cast<std::int32_t>(f.extremitiesMatched));
  w.put(static_cast<std::uint8_t>(f.continuesPrevious));
  w.put(static_cast<std::uint32_t>(f.extremities.size()));
  for (const Vec3& e : f.extremities)
    for (int c = 0; c < 3; ++c) w.put(e[c]);
}

BodyFrameFit getFit(ByteReader& r)
{
  BodyFrameFit f;
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) f.pose.rotations(j, c) = r.get<double>();
  for (int c = 0; c < 3; ++c) f.pose.translation[c] = r.get<double>();
  f.status = static_cast<BodyFitStatus>(r.get<std::int32_t>());
  f.message = r.getText();
  for (double* v : {&f.energy, &f.medianDistance, &f.insideFraction, &f.frameDistance,
                    &f.previousGap, &f.rivalScoreRatio})
    *v = r.get<double>();
  f.extremitiesDetected = r.get<std::int32_t>();
  f.extremitiesMatched = r.get<std::int32_t>();
  f.continuesPrevious = r.get<std::uint8_t>() != 0;
  f.extremities.resize(r.get<std::uint32_t>());
  for (Vec3& e : f.extremities)
    for (int c = 0; c < 3; ++c) e[c] = r.get<double>();
  return f;
}
} // namespace

std::string encodeFrameFits(const std::vector<BodyFrameFit>& fits, const std::vector<int>& frames)
{
  ByteWriter w;
  w.put(kLayout);
  w.put(static_cast<std::uint32_t>(frames.size()));
  for (int i : frames)
  {
    w.put(static_cast<std::int32_t>(i));
    putFit(w, fits.at(i));
  }
  return w.take();
}

void decodeFrameFits(const std::string& bytes, std::vector<BodyFrameFit>& fits)
{
  ByteReader r(bytes, "shared body fit");
  if (r.get<std::uint32_t>() != kLayout) throw Error("shared body fit: message of another layout");
  const auto count = r.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < count; ++k)
  {
    const auto i = r.get<std::int32_t>();
    if (i < 0 || i >= static_cast<std::int32_t>(fits.size()))
      throw Error("shared body fit: frame " + std::to_string(i) + " out of range");
    fits[i] = getFit(r);
  }
  r.expectEnd();
}
} // namespace clothtrack
