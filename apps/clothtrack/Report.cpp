#include "Report.h"

#include "Commands.h"

#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace clothtrack::app
{
namespace
{
bool onPath(const std::string& program)
{
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size())
  {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::filesystem::path candidate =
        std::filesystem::path(dirs.substr(start, end - start)) / program;
    if (access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

/// The package beside this build (or installed): CLOTHTRACK_PYTHONPATH overrides it.
std::string packageDirectory()
{
  if (const char* own = std::getenv("CLOTHTRACK_PYTHONPATH")) return own;
  return CLOTHTRACK_PYTHON_DIR;
}
} // namespace

void writeReport(const std::string& folder)
{
  runPackageModule("clothtrack.report", folder, {});
}

void writeMovie(const std::string& folder, const std::vector<std::string>& options)
{
  runPackageModule("clothtrack.movie", folder, options);
}

void runPackageModule(const std::string& module, const std::string& folder,
                      const std::vector<std::string>& options)
{
  if (!std::filesystem::is_regular_file(std::filesystem::path(folder) / "metrics.json"))
    throw UsageError{folder + ": no metrics.json (run 'clothtrack align' first)"};
  const std::string python = CLOTHTRACK_PYTHON_EXECUTABLE;
  // Without a display the module renders on a virtual one of its own (clothtrack.virtual_display).
  const char* display = std::getenv("DISPLAY");
  if ((!display || !*display) && !onPath("Xvfb"))
    throw UsageError{"renders need an X display or Xvfb (Debian package: xvfb)"};
  std::vector<std::string> command{python, "-m", module, folder};
  command.insert(command.end(), options.begin(), options.end());

  const std::string pythonPath = packageDirectory();
  const pid_t child = fork();
  if (child < 0) throw UsageError{module + ": cannot start " + python};
  if (child == 0)
  {
    const char* old = std::getenv("PYTHONPATH");
    const std::string value = pythonPath + (old && *old ? std::string(":") + old : "");
    setenv("PYTHONPATH", value.c_str(), 1);
    std::vector<char*> argv;
    for (std::string& part : command) argv.push_back(part.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw UsageError{module + ": '" + command.front() + " ... " + module + "' failed (exit " +
                     std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                     "); the aligned sequence and metrics.json are written"};
}
} // namespace clothtrack::app
