#pragma once
// Helpers shared by the VTK-layer tests.
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>

#include <string>

namespace clothtrack::test
{
/// Records the first error or warning an algorithm reports (instead of printing it).
struct ErrorWatch
{
  std::string message;
  vtkNew<vtkCallbackCommand> command;
  explicit ErrorWatch(vtkObject* object)
  {
    command->SetClientData(this);
    command->SetCallback(
        [](vtkObject*, unsigned long, void* client, void* data)
        {
          auto* self = static_cast<ErrorWatch*>(client);
          if (self->message.empty()) self->message = static_cast<const char*>(data);
        });
    object->AddObserver(vtkCommand::ErrorEvent, command);
    object->AddObserver(vtkCommand::WarningEvent, command);
  }
};
} // namespace clothtrack::test
