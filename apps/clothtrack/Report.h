#pragma once
// The HTML report of an aligned sequence, drawn by the clothtrack Python package.
#include <string>

namespace clothtrack::app
{
/// Runs 'python3 -m clothtrack.report folder' (under xvfb-run when there is no display);
/// UsageError with the reason when it fails.
void writeReport(const std::string& folder);
} // namespace clothtrack::app
