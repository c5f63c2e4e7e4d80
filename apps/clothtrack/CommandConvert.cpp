// clothtrack convert: read a sequence (any supported format, units, up axis) and write it as a
// ParaView collection, frame by frame so that memory does not grow with the sequence length.
#include "Commands.h"
#include "Options.h"
#include "Progress.h"
#include "ctArrayNames.h"

#include "ctMeshConversion.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <clothtrack/io/FrameList.h>

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace clothtrack::app
{
int runConvert(const Args& args)
{
  std::string input, output;
  bool obj = false;
  SequenceOptions seq;
  po::options_description options("convert options");
  options.add_options()("input", po::value(&input)->required(),
                        "folder, glob pattern, list file or mesh file")(
      "output,o", po::value(&output)->required(),
      "output collection (.pvd); frames go to a folder beside it")("obj", po::bool_switch(&obj),
                                                                   "also write each frame as OBJ");
  addSequenceOptions(options, seq);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack convert INPUT -o OUT.pvd [options]", options, positional,
                    values))
    return 0;
  resolveAutomatic(seq, input);
  const FrameConventions conventions = toConventions(seq);
  if (fs::path(output).extension() != ".pvd")
    throw UsageError{"--output must end in .pvd (got '" + output + "')"};

  const std::vector<std::string> frames = listFrames(input);
  std::vector<std::pair<double, std::string>> entries;
  Progress progress("convert", static_cast<int>(frames.size()));
  for (size_t k = 0; k < frames.size(); ++k)
  {
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadFrame(frames[k], conventions, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    vtkSmartPointer<vtkPolyData> poly = toPolyData(mesh);
    vtkNew<vtkStringArray> source;
    source->SetName(clothtrack::arrays::SourceFile);
    source->InsertNextValue(frames[k]);
    poly->GetFieldData()->AddArray(source);
    const std::string relative = writeCollectionFrame(output, static_cast<int>(k), poly, obj);
    entries.emplace_back(k / seq.fps, relative);
    progress.step(static_cast<int>(k + 1));
  }
  progress.finish();
  writeCollection(output, entries);
  std::printf("wrote %zu frames to %s\n", frames.size(), output.c_str());
  return 0;
}
} // namespace clothtrack::app
