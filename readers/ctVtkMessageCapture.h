#pragma once
// VTK's readers report many problems not through the reader but through the objects behind it
// (its executive, its arrays, the XML parser), straight to the process's output window: blocks
// of several lines printed before ClothTrack's own one-line error. While a capture is alive on a
// thread, every message VTK sends to the output window from that thread is collected instead;
// other threads and other times go to the window that was installed before.
#include <string>
#include <vector>

namespace clothtrack
{
/// A VTK error or warning text reduced to the message itself: no "ERROR: In FILE, line N"
/// heading, no "vtkClass (0x...): " prefix naming an object the user never saw.
std::string plainVtkMessage(const std::string& text);

class VtkMessageCapture
{
public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

  /// The first collected error or warning, reduced to the message itself (VTK puts the source
  /// location and the emitting object before it); empty when none came.
  std::string firstMessage() const;

private:
  std::vector<std::string> messages_;
  std::vector<std::string>* enclosing_;
};
} // namespace clothtrack
