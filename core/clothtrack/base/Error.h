#pragma once
// Errors raised by the VTK-free core. Messages are complete sentences meant for users: the VTK
// wrappers forward them through vtkErrorMacro and the apps print them as one line.
#include <stdexcept>
#include <string>

namespace clothtrack
{
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};
} // namespace clothtrack
