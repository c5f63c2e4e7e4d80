#include "AlignCache.h"

#include "BodyFitRun.h"
#include "Commands.h"
#include "StoredLandmarks.h"
#include "TextFile.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace clothtrack::app
{
namespace
{
constexpr char kTargetsMagic[8] = {'C', 'T', 'T', 'G', 'T', '0', '0', '1'};
constexpr char kFitterStateMagic[8] = {'C', 'T', 'F', 'S', 'T', '0', '0', '1'};

template <class T> void put(std::ostream& out, const T& value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(value));
}
template <class T> bool get(std::istream& in, T& value)
{
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(value)));
}

} // namespace

void writeBodyFitJson(const std::string& path, const std::string& modelPath,
                      const std::vector<std::string>& files, const BodyStage& stage)
{
  const nlohmann::json head = {{"model", modelPath},
                               {"beta", coefficientsJson(stage.body.beta)},
                               {"moved_shape", stage.body.movedShape},
                               {"other_beta", coefficientsJson(stage.body.otherBeta)},
                               {"shape_gap_m", stage.body.shapeGap}};
  std::string text = head.dump(1);
  text.pop_back(); // the closing brace: the frames follow
  AtomicTextFile file(path);
  file << text << ",\n \"per_frame\": [";
  for (size_t k = 0; k < stage.body.frames.size(); ++k)
    file << (k ? ",\n" : "\n") << bodyFrameJson(files[k], stage.body.frames[k]).dump();
  file << "\n ]\n}\n";
  file.commit();
}

void writeBodyStage(const std::string& path, const nlohmann::json& key,
                    const std::vector<std::string>& files, BodyStage& stage)
{
  AtomicTextFile file(path);
  file << nlohmann::json({{"key", key},
                          {"beta", coefficientsJson(stage.body.beta)},
                          {"moved_shape", stage.body.movedShape},
                          {"other_beta", coefficientsJson(stage.body.otherBeta)},
                          {"shape_gap_m", stage.body.shapeGap},
                          {"frames", stage.landmarks.size()}})
              .dump()
       << "\n";
  stage.lineOffsets.clear();
  stage.landmarkCounts.clear();
  for (size_t k = 0; k < stage.landmarks.size(); ++k)
  {
    const nlohmann::json body =
        k < stage.body.frames.size() ? bodyFrameJson(files[k], stage.body.frames[k]) : nullptr;
    stage.lineOffsets.push_back(static_cast<std::int64_t>(file.written()));
    stage.landmarkCounts.push_back(static_cast<int>(stage.landmarks[k].size()));
    file
        << nlohmann::json({{"body", body}, {"landmarks", landmarksJson(stage.landmarks[k])}}).dump()
        << "\n";
  }
  file.commit();
}

std::optional<BodyStage> readBodyStage(const std::string& path, const nlohmann::json& key)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  try
  {
    std::string line;
    if (!std::getline(in, line)) return std::nullopt;
    const nlohmann::json head = nlohmann::json::parse(line);
    if (head.at("key") != key) return std::nullopt;
    BodyStage out;
    out.body.beta = coefficients(head.at("beta"));
    out.body.movedShape = head.at("moved_shape").get<bool>();
    out.body.otherBeta = coefficients(head.at("other_beta"));
    out.body.shapeGap = head.at("shape_gap_m").get<double>();
    const auto frames = head.at("frames").get<size_t>();
    auto offset = static_cast<std::int64_t>(in.tellg());
    while (out.lineOffsets.size() < frames && std::getline(in, line))
    {
      const nlohmann::json record = nlohmann::json::parse(line);
      if (!record.at("body").is_null()) out.body.frames.push_back(bodyFrameFit(record["body"]));
      out.lineOffsets.push_back(offset);
      out.landmarkCounts.push_back(
          static_cast<int>(landmarksFromJson(record.at("landmarks")).size()));
      offset = static_cast<std::int64_t>(in.tellg());
    }
    if (out.lineOffsets.size() != frames) return std::nullopt; // cut short
    return out;
  }
  catch (const std::exception&) // unreadable or of another model
  {
    return std::nullopt; // recomputed
  }
}

void writeTargets(const std::string& path, const std::string& frameFile,
                  const VertexTargets& targets)
{
  const std::string part = path + ".part";
  {
    std::ofstream out(part, std::ios::binary);
    const auto nameLength = static_cast<std::uint32_t>(frameFile.size());
    const auto n = static_cast<std::uint32_t>(targets.matched.size());
    out.write(kTargetsMagic, sizeof(kTargetsMagic));
    out.write(reinterpret_cast<const char*>(&nameLength), sizeof(nameLength));
    out.write(frameFile.data(), nameLength);
    out.write(reinterpret_cast<const char*>(&n), sizeof(n));
    out.write(reinterpret_cast<const char*>(targets.matched.data()), n);
    for (std::uint32_t i = 0; i < n; ++i)
    {
      const double p[3] = {targets.position(i, 0), targets.position(i, 1), targets.position(i, 2)};
      out.write(reinterpret_cast<const char*>(p), sizeof(p));
    }
    if (!out.flush()) throw UsageError{path + ": cannot write file"};
  }
  std::error_code error;
  std::filesystem::rename(part, path, error);
  if (error) throw UsageError{path + ": cannot write file (" + error.message() + ")"};
}

std::optional<VertexTargets> readTargets(const std::string& path, const std::string& frameFile,
                                         int templateVertices)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[sizeof(kTargetsMagic)];
  std::uint32_t nameLength = 0, n = 0;
  if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kTargetsMagic, sizeof(magic)) != 0 ||
      !in.read(reinterpret_cast<char*>(&nameLength), sizeof(nameLength)) ||
      nameLength != frameFile.size())
    return std::nullopt;
  std::string name(nameLength, '\0');
  if (!in.read(name.data(), nameLength) || name != frameFile ||
      !in.read(reinterpret_cast<char*>(&n), sizeof(n)) ||
      n != static_cast<std::uint32_t>(templateVertices))
    return std::nullopt;
  VertexTargets targets;
  targets.matched.resize(n);
  targets.position.resize(n, 3);
  if (!in.read(reinterpret_cast<char*>(targets.matched.data()), n)) return std::nullopt;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    double p[3];
    if (!in.read(reinterpret_cast<char*>(p), sizeof(p))) return std::nullopt;
    targets.position.row(i) << p[0], p[1], p[2];
  }
  return targets;
}

void writeFitterState(const std::string& path, const TemplateFitterState& state)
{
  const std::string part = path + ".part";
  {
    std::ofstream out(part, std::ios::binary);
    out.write(kFitterStateMagic, sizeof(kFitterStateMagic));
    put(out, static_cast<std::uint32_t>(state.vertices));
    put(out, static_cast<std::uint32_t>(state.stages.size()));
    for (const TemplateFitterState::Stage& stage : state.stages)
    {
      put(out, static_cast<std::uint8_t>(stage.factored));
      put(out, static_cast<std::uint8_t>(stage.stale));
      put(out, stage.edgeWeight);
      put(out, static_cast<std::uint64_t>(stage.blocks.size()));
      out.write(reinterpret_cast<const char*>(stage.blocks.data()),
                static_cast<std::streamsize>(stage.blocks.size() * sizeof(double)));
    }
    if (!out.flush()) throw UsageError{path + ": cannot write file"};
  }
  std::error_code error;
  std::filesystem::rename(part, path, error);
  if (error) throw UsageError{path + ": cannot write file (" + error.message() + ")"};
}

std::optional<TemplateFitterState> readFitterState(const std::string& path, int templateVertices)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[sizeof(kFitterStateMagic)];
  std::uint32_t vertices = 0, stages = 0;
  if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kFitterStateMagic, sizeof(magic)) != 0 ||
      !get(in, vertices) || vertices != static_cast<std::uint32_t>(templateVertices) ||
      !get(in, stages) || stages > 64)
    return std::nullopt;
  TemplateFitterState state;
  state.vertices = templateVertices;
  state.stages.resize(stages);
  for (TemplateFitterState::Stage& stage : state.stages)
  {
    std::uint8_t factored = 0, stale = 0;
    std::uint64_t count = 0;
    if (!get(in, factored) || !get(in, stale) || !get(in, stage.edgeWeight) || !get(in, count) ||
        (count != 0 && count != 10 * static_cast<std::uint64_t>(templateVertices)))
      return std::nullopt;
    stage.factored = factored != 0;
    stage.stale = stale != 0;
    stage.blocks.resize(count);
    if (!in.read(reinterpret_cast<char*>(stage.blocks.data()),
                 static_cast<std::streamsize>(count * sizeof(double))))
      return std::nullopt;
  }
  return state;
}
} // namespace clothtrack::app
