// One mesh reader under libFuzzer: the input bytes become a file with the extension this target
// was built for, read as the app reads a frame. An Error is the expected answer to bad bytes;
// anything else (a crash, a sanitizer report, another exception, a hang) is a finding.
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkLogger.h>
#include <vtkObject.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{
std::string scratchFile()
{
  const char* dir = std::getenv("CLOTHTRACK_FUZZ_TMP");
  return std::string(dir ? dir : "/tmp") + "/clothtrack_fuzz_" + std::to_string(getpid()) +
         FUZZ_EXTENSION;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkObject::GlobalWarningDisplayOff();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const std::string path = scratchFile();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return 0;
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  try
  {
    clothtrack::TriangleMesh mesh = clothtrack::readMeshFile(path);
    clothtrack::validateAndClean(mesh, path);
  }
  catch (const clothtrack::Error&)
  {
  }
  return 0;
}
