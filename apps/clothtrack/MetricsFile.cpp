#include "MetricsFile.h"

#include "Commands.h"

#include <fstream>

namespace clothtrack::app
{
nlohmann::json readMetrics(const std::filesystem::path& path)
{
  std::ifstream in(path);
  if (!in) throw UsageError{path.string() + ": no metrics.json (run 'clothtrack align' first)"};
  try
  {
    return nlohmann::json::parse(in);
  }
  catch (const nlohmann::json::exception& e)
  {
    throw UsageError{path.string() + ": not valid JSON (" + e.what() + ")"};
  }
}
} // namespace clothtrack::app
