#include "MakeHumanImport.h"

#include "BodyModelBuilder.h"
#include <clothtrack/base/Error.h>
#include <clothtrack/io/MeshIO.h>
#include <clothtrack/mesh/MeshTopology.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace clothtrack
{
namespace
{
constexpr double kDecimetre = 0.1;

nlohmann::json readJson(const fs::path& path)
{
  std::ifstream in(path);
  if (!in) throw Error(path.string() + ": cannot open file");
  try
  {
    return nlohmann::json::parse(in);
  }
  catch (const nlohmann::json::exception& e)
  {
    throw Error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

// A target file: sparse per-vertex displacements ("index dx dy dz" lines, # comments).
std::vector<std::pair<int, Vec3>> readTarget(const fs::path& path, int numVertices)
{
  std::ifstream in(path);
  if (!in) throw Error(path.string() + ": cannot open target file");
  std::vector<std::pair<int, Vec3>> offsets;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line))
  {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    int index;
    Vec3 d;
    if (!(words >> index >> d.x() >> d.y() >> d.z()) || index < 0 || index >= numVertices)
      throw Error(path.string() + ":" + std::to_string(lineNo) + ": malformed target line");
    offsets.emplace_back(index, d);
  }
  return offsets;
}

// ClothTrack joint of the main MakeHuman bones; others inherit their parent's.
int mappedJoint(const std::string& bone)
{
  static const std::map<std::string, int> map = {{"root", Pelvis},
                                                 {"spine05", Pelvis},
                                                 {"spine04", Pelvis},
                                                 {"pelvis.L", Pelvis},
                                                 {"pelvis.R", Pelvis},
                                                 {"spine03", Spine1},
                                                 {"spine02", Spine2},
                                                 {"spine01", Spine3},
                                                 {"breast.L", Spine3},
                                                 {"breast.R", Spine3},
                                                 {"neck01", Neck},
                                                 {"neck02", Neck},
                                                 {"neck03", Neck},
                                                 {"head", Head},
                                                 {"clavicle.L", LeftClavicle},
                                                 {"shoulder01.L", LeftClavicle},
                                                 {"upperarm01.L", LeftShoulder},
                                                 {"upperarm02.L", LeftShoulder},
                                                 {"lowerarm01.L", LeftElbow},
                                                 {"lowerarm02.L", LeftElbow},
                                                 {"wrist.L", LeftWrist},
                                                 {"clavicle.R", RightClavicle},
                                                 {"shoulder01.R", RightClavicle},
                                                 {"upperarm01.R", RightShoulder},
                                                 {"upperarm02.R", RightShoulder},
                                                 {"lowerarm01.R", RightElbow},
                                                 {"lowerarm02.R", RightElbow},
                                                 {"wrist.R", RightWrist},
                                                 {"upperleg01.L", LeftHip},
                                                 {"upperleg02.L", LeftHip},
                                                 {"lowerleg01.L", LeftKnee},
                                                 {"lowerleg02.L", LeftKnee},
                                                 {"foot.L", LeftAnkle},
                                                 {"upperleg01.R", RightHip},
                                                 {"upperleg02.R", RightHip},
                                                 {"lowerleg01.R", RightKnee},
                                                 {"lowerleg02.R", RightKnee},
                                                 {"foot.R", RightAnkle}};
  if (bone.rfind("toe", 0) == 0) // toes have no parent chain to a mapped bone but the foot
    return bone.back() == 'L' ? LeftToe : RightToe;
  const auto it = map.find(bone);
  return it == map.end() ? -1 : it->second;
}

// Bone whose head gives each ClothTrack joint.
const std::array<const char*, NumJoints>& jointBones()
{
  static const std::array<const char*, NumJoints> bones = {
      "spine05",      "spine03",      "spine02",      "spine01",      "neck01",     "head",
      "clavicle.L",   "upperarm01.L", "lowerarm01.L", "wrist.L",      "clavicle.R", "upperarm01.R",
      "lowerarm01.R", "wrist.R",      "upperleg01.L", "lowerleg01.L", "foot.L",     "toe3-1.L",
      "upperleg01.R", "lowerleg01.R", "foot.R",       "toe3-1.R"};
  return bones;
}

// MakeHuman-style weights of the three levels (min, average, max) of a macro value in [0, 1].
std::array<double, 3> levels(double v)
{
  return {std::max(0.0, 1 - 2 * v), 1 - std::abs(2 * v - 1), std::max(0.0, 2 * v - 1)};
}
} // namespace

BodyModel importMakeHuman(const std::string& folderName, const MakeHumanImportOptions& options)
{
  const fs::path folder(folderName);
  for (const char* required :
       {"base.obj", "default.mhskel", "default_weights.mhw", "targets/macrodetails"})
    if (!fs::exists(folder / required))
      throw Error((folder / required).string() + ": missing (not a MakeHuman asset folder?)");

  // Mesh: every vertex (targets and joints index them), the body faces only.
  const TriangleMesh full = readOBJ((folder / "base.obj").string(), "body");
  if (full.numFaces() == 0)
    throw Error((folder / "base.obj").string() + ": no face in group 'body'");
  const int numAll = full.numVertices();

  // Skeleton joints: mean of the helper vertices named in the skeleton file.
  const nlohmann::json skeleton = readJson(folder / "default.mhskel");
  const auto& bones = skeleton.at("bones");
  const auto& jointVertices = skeleton.at("joints");
  auto bonePosition = [&](const std::string& bone, const Points& V) -> Vec3
  {
    if (!bones.contains(bone))
      throw Error((folder / "default.mhskel").string() + ": no bone '" + bone + "'");
    const std::string head = bones.at(bone).at("head");
    Vec3 sum = Vec3::Zero();
    const auto& ids = jointVertices.at(head);
    for (int id : ids) sum += V.row(id).transpose();
    return sum / static_cast<double>(ids.size());
  };

  // Used body vertices, renumbered.
  std::vector<int> newIndex(numAll, -1), oldIndex;
  for (int f = 0; f < full.numFaces(); ++f)
    for (int c = 0; c < 3; ++c)
      if (newIndex[full.F(f, c)] < 0)
      {
        newIndex[full.F(f, c)] = static_cast<int>(oldIndex.size());
        oldIndex.push_back(full.F(f, c));
      }
  TriangleMesh body;
  body.F.resize(full.numFaces(), 3);
  for (int f = 0; f < full.numFaces(); ++f)
    for (int c = 0; c < 3; ++c) body.F(f, c) = newIndex[full.F(f, c)];
  const int nBody = static_cast<int>(oldIndex.size());
  body.V.resize(nBody, 3);
  for (int i = 0; i < nBody; ++i) body.V.row(i) = full.V.row(oldIndex[i]);

  // Holes (eye sockets, ...) closed by a fan around their centre.
  const std::vector<std::vector<int>> loops = boundaryLoops(body, buildTopology(body));
  const int n = nBody + static_cast<int>(loops.size());
  {
    Triangles F(body.numFaces() + static_cast<int>(
                                      [&]
                                      {
                                        size_t s = 0;
                                        for (auto& l : loops) s += l.size();
                                        return s;
                                      }()),
                3);
    F.topRows(body.numFaces()) = body.F;
    int f = body.numFaces();
    for (size_t l = 0; l < loops.size(); ++l)
      for (size_t k = 0; k < loops[l].size(); ++k)
        F.row(f++) << loops[l][(k + 1) % loops[l].size()], loops[l][k], nBody + static_cast<int>(l);
    body.F = F;
  }
  auto bodyVertices = [&](const Points& all) -> Points
  {
    Points V(n, 3);
    for (int i = 0; i < nBody; ++i) V.row(i) = all.row(oldIndex[i]);
    for (size_t l = 0; l < loops.size(); ++l)
    {
      Vec3 c = Vec3::Zero();
      for (int v : loops[l]) c += V.row(v).transpose();
      V.row(nBody + static_cast<int>(l)) = (c / static_cast<double>(loops[l].size())).transpose();
    }
    return V;
  };

  // Skinning: MakeHuman bone weights summed per ClothTrack joint.
  const nlohmann::json weightsFile = readJson(folder / "default_weights.mhw");
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(n, NumJoints);
  for (const auto& [bone, list] : weightsFile.at("weights").items())
  {
    int joint = mappedJoint(bone);
    std::string b = bone;
    for (int guard = 0; joint < 0 && guard < 20 && bones.contains(b); ++guard)
    {
      const auto& parent = bones.at(b).at("parent");
      if (parent.is_null()) break;
      b = parent.get<std::string>();
      joint = mappedJoint(b);
    }
    if (joint < 0) joint = Head; // face and eye helpers
    for (const auto& entry : list)
    {
      const int v = entry.at(0);
      if (v >= 0 && v < numAll && newIndex[v] >= 0)
        weights(newIndex[v], joint) += entry.at(1).get<double>();
    }
  }
  for (size_t l = 0; l < loops.size(); ++l)
  {
    for (int v : loops[l]) weights.row(nBody + static_cast<int>(l)) += weights.row(v);
  }
  for (int i = 0; i < n; ++i)
  {
    const double sum = weights.row(i).sum();
    if (sum > 0)
      weights.row(i) /= sum;
    else
      weights(i, Pelvis) = 1.0; // unweighted vertex: follows the body
  }

  // Macro targets.
  const fs::path macro = folder / "targets/macrodetails";
  const char* genders[2] = {"female", "male"};
  const char* ages[2] = {"young", "old"};
  const char* muscles[3] = {"minmuscle", "averagemuscle", "maxmuscle"};
  const char* weightNames[3] = {"minweight", "averageweight", "maxweight"};
  std::map<std::string, std::vector<std::pair<int, Vec3>>> targets;
  for (const auto& g : genders)
    for (const auto& a : ages)
      for (const auto& m : muscles)
        for (const auto& w : weightNames)
        {
          const std::string base = std::string(g) + "-" + a + "-" + m + "-" + w;
          targets["u/" + base] = readTarget(macro / ("universal-" + base + ".target"), numAll);
          for (const char* h : {"minheight", "maxheight"})
          {
            const fs::path file = macro / "height" / (base + "-" + h + ".target");
            if (fs::exists(file)) targets["h/" + base + "-" + h] = readTarget(file, numAll);
          }
        }

  // Population of macro settings.
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int N = options.populationSize;
  Eigen::MatrixXd X(N, 3 * n + 3 * NumJoints);
  for (int s = 0; s < N; ++s)
  {
    const double gender = uniform(rng), age = 0.5 * uniform(rng);
    const auto muscle = levels(0.15 + 0.7 * uniform(rng)),
               weight = levels(0.15 + 0.7 * uniform(rng));
    const double height = uniform(rng);
    const auto heightLevels = levels(height);
    Points all = full.V;
    for (int g = 0; g < 2; ++g)
      for (int a = 0; a < 2; ++a)
        for (int m = 0; m < 3; ++m)
          for (int w = 0; w < 3; ++w)
          {
            const double wg =
                (g == 0 ? 1 - gender : gender) * (a == 0 ? 1 - age : age) * muscle[m] * weight[w];
            if (wg <= 0) continue;
            const std::string base =
                std::string(genders[g]) + "-" + ages[a] + "-" + muscles[m] + "-" + weightNames[w];
            for (const auto& [v, d] : targets["u/" + base]) all.row(v) += wg * d.transpose();
            for (int h : {0, 2})
            {
              const auto it = targets.find("h/" + base + (h == 0 ? "-minheight" : "-maxheight"));
              if (it != targets.end() && heightLevels[h] > 0)
                for (const auto& [v, d] : it->second)
                  all.row(v) += wg * heightLevels[h] * d.transpose();
            }
          }
    Points V = bodyVertices(all);
    Points J(NumJoints, 3);
    for (int j = 0; j < NumJoints; ++j) J.row(j) = bonePosition(jointBones()[j], all).transpose();
    // Metres, feet on the floor.
    const double floor = V.col(1).minCoeff();
    V.col(1).array() -= floor;
    J.col(1).array() -= floor;
    V *= kDecimetre;
    J *= kDecimetre;
    X.row(s).head(3 * n) = Eigen::Map<const Eigen::RowVectorXd>(V.data(), 3 * n);
    X.row(s).tail(3 * NumJoints) = Eigen::Map<const Eigen::RowVectorXd>(J.data(), 3 * NumJoints);
  }

  if (signedVolume(TriangleMesh{bodyVertices(full.V), body.F}) < 0)
    body.F.col(1).swap(body.F.col(2)); // body models face outward
  BodyModel model;
  model.weights = weights;
  learnShapeSpace(std::move(X), body.F, options.numComponents, model);

  // Landmarks on the mean body, with its skeleton.
  SkeletonGeometry skeletonGeometry;
  skeletonGeometry.joints = model.joints;
  skeletonGeometry.boneEnds = model.joints;
  setInnerBoneEnds(skeletonGeometry);
  const double stature = model.mesh.V.col(1).maxCoeff() - model.mesh.V.col(1).minCoeff();
  skeletonGeometry.boneEnds.row(Head) =
      (model.joints.row(Head).transpose() +
       Vec3(0, model.mesh.V.col(1).maxCoeff() - model.joints(Head, 1), 0))
          .transpose();
  for (int wrist : {LeftWrist, RightWrist})
  {
    const int elbow = wrist == LeftWrist ? LeftElbow : RightElbow;
    const Vec3 dir = (model.joints.row(wrist) - model.joints.row(elbow)).normalized().transpose();
    skeletonGeometry.boneEnds.row(wrist) =
        (model.joints.row(wrist).transpose() + 0.1 * stature * dir).transpose();
  }
  for (int toe : {LeftToe, RightToe})
    skeletonGeometry.boneEnds.row(toe) =
        (model.joints.row(toe).transpose() + Vec3(0, 0, 0.04 * stature)).transpose();
  model.landmarks = findLandmarks(model.mesh, skeletonGeometry, stature);
  return model;
}
} // namespace clothtrack
