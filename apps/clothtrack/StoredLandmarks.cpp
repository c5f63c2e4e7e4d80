#include "StoredLandmarks.h"

#include <clothtrack/base/Error.h>

#include <fstream>
#include <stdexcept>

namespace clothtrack::app
{
nlohmann::json landmarksJson(const FrameLandmarks& landmarks)
{
  nlohmann::json list = nlohmann::json::array();
  for (const OrientedSurfacePoint& p : landmarks)
    list.push_back({p.id, p.face, p.bary.x(), p.bary.y(), p.bary.z(), p.direction.x(),
                    p.direction.y(), p.direction.z(), p.offset});
  return list;
}

FrameLandmarks landmarksFromJson(const nlohmann::json& list)
{
  FrameLandmarks out;
  for (const auto& p : list)
  {
    if (p.size() != 9) throw std::runtime_error("not a landmark");
    out.push_back({p[0].get<int>(),
                   p[1].get<int>(),
                   {p[2].get<double>(), p[3].get<double>(), p[4].get<double>()},
                   {p[5].get<double>(), p[6].get<double>(), p[7].get<double>()},
                   p[8].get<double>()});
  }
  return out;
}

StoredLandmarks::StoredLandmarks(int frames)
    : counts_(frames, 0), held_(frames), kept_(frames, false)
{
}

StoredLandmarks::StoredLandmarks(std::vector<FrameLandmarks> landmarks)
    : held_(landmarks.size()), kept_(landmarks.size(), true)
{
  for (size_t k = 0; k < landmarks.size(); ++k)
  {
    counts_.push_back(static_cast<int>(landmarks[k].size()));
    held_[k] = std::make_shared<const FrameLandmarks>(std::move(landmarks[k]));
  }
}

StoredLandmarks::StoredLandmarks(std::string path, std::vector<std::int64_t> lineOffsets,
                                 std::vector<int> counts)
    : path_(std::move(path)), offsets_(std::move(lineOffsets)), counts_(std::move(counts)),
      held_(counts_.size()), kept_(counts_.size(), false)
{
  if (offsets_.size() != counts_.size())
    throw Error(path_ + ": " + std::to_string(offsets_.size()) + " lines for " +
                std::to_string(counts_.size()) + " frames");
}

const FrameLandmarks& StoredLandmarks::operator[](int k)
{
  const std::lock_guard<std::mutex> lock(*mutex_);
  std::shared_ptr<const FrameLandmarks>& held = held_.at(k);
  if (!held)
    held = std::make_shared<const FrameLandmarks>(counts_[k] > 0 ? read(k) : FrameLandmarks());
  return *held;
}

void StoredLandmarks::release(int k)
{
  const std::lock_guard<std::mutex> lock(*mutex_);
  if (k >= 0 && k < frames() && !kept_[k]) held_[k].reset();
}

void StoredLandmarks::keep(int k)
{
  const std::lock_guard<std::mutex> lock(*mutex_);
  kept_.at(k) = true;
}

FrameLandmarks StoredLandmarks::read(int k) const
{
  std::ifstream in(path_, std::ios::binary);
  std::string line;
  if (!in.seekg(offsets_[k]) || !std::getline(in, line))
    throw Error(path_ + ": cannot read the landmarks of frame " + std::to_string(k) +
                " (the file changed during the run?)");
  try
  {
    FrameLandmarks landmarks = landmarksFromJson(nlohmann::json::parse(line).at("landmarks"));
    if (static_cast<int>(landmarks.size()) != counts_[k]) throw std::runtime_error("count");
    return landmarks;
  }
  catch (const std::exception&)
  {
    throw Error(path_ + ": the landmarks of frame " + std::to_string(k) +
                " changed during the run");
  }
}
} // namespace clothtrack::app
