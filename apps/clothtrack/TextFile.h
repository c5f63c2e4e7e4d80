#pragma once
// Writing small text outputs (JSON, CSV) so that no half-written file is ever taken for a
// result: write beside, then rename.
#include <string>

namespace clothtrack::app
{
/// Writes `text` to path.part then renames it to path; UsageError when it cannot.
void writeTextAtomically(const std::string& path, const std::string& text);
} // namespace clothtrack::app
