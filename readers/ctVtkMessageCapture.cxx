#include "ctVtkMessageCapture.h"

#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <mutex>
#include <sstream>

namespace clothtrack
{
namespace
{
thread_local std::vector<std::string>* activeSink = nullptr;

// Collects into the calling thread's active capture; forwards everything else to the window
// that was the instance before it.
class ctCapturingOutputWindow : public vtkOutputWindow
{
public:
  static ctCapturingOutputWindow* New();
  vtkTypeMacro(ctCapturingOutputWindow, vtkOutputWindow);

  void DisplayText(const char* text) override
  {
    if (!collect(text)) Previous->DisplayText(text);
  }
  void DisplayErrorText(const char* text) override
  {
    if (!collect(text)) Previous->DisplayErrorText(text);
  }
  void DisplayWarningText(const char* text) override
  {
    if (!collect(text)) Previous->DisplayWarningText(text);
  }
  void DisplayGenericWarningText(const char* text) override
  {
    if (!collect(text)) Previous->DisplayGenericWarningText(text);
  }
  void DisplayDebugText(const char* text) override
  {
    if (!activeSink) Previous->DisplayDebugText(text);
  }

  vtkSmartPointer<vtkOutputWindow> Previous;

private:
  static bool collect(const char* text)
  {
    if (!activeSink) return false;
    activeSink->emplace_back(text ? text : "");
    return true;
  }
};
vtkStandardNewMacro(ctCapturingOutputWindow);

void installOnce()
{
  static std::once_flag once;
  std::call_once(once,
                 []
                 {
                   vtkNew<ctCapturingOutputWindow> window;
                   window->Previous = vtkOutputWindow::GetInstance();
                   vtkOutputWindow::SetInstance(window);
                 });
}

} // namespace

VtkMessageCapture::VtkMessageCapture() : enclosing_(activeSink)
{
  installOnce();
  activeSink = &messages_;
}

VtkMessageCapture::~VtkMessageCapture()
{
  activeSink = enclosing_;
}

// The first line after VTK's "ERROR: In FILE, line N" heading, without the
// "vtkClass (0x...): " prefix that names an object the user never saw.
std::string plainVtkMessage(const std::string& text)
{
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
  {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty() && line.find(": In ") == std::string::npos) break;
    line.clear();
  }
  const auto address = line.find(" (0x");
  const auto colon = line.find("): ");
  if (address != std::string::npos && colon != std::string::npos && address < colon &&
      line.find(' ') == address)
    line = line.substr(colon + 3);
  return line;
}

std::string VtkMessageCapture::firstMessage() const
{
  for (const std::string& m : messages_)
  {
    // An executive's report that its algorithm failed only follows the algorithm's own.
    const std::string line = plainVtkMessage(m);
    if (!line.empty() && line.find("returned failure for request") == std::string::npos)
      return line;
  }
  return {};
}
} // namespace clothtrack
