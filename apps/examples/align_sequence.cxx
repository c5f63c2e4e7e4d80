// The ClothTrack pipeline as a C++ filter chain:
//   sequence reader -> body fit -> patch correspondence -> template fit -> alignment error ->
//   writer
//
// usage: example_align_sequence FRAMES GROUND_TRUTH OUT.pvd
//
// FRAMES and GROUND_TRUTH are folders of frames (e.g. the frames/ and ground_truth/ folders that
// `clothtrack synth` writes). Prints the per-frame errors and writes the aligned sequence, with its
// Error array, as OUT.pvd + one .vtp per frame.
#include "ctAlignmentError.h"
#include "ctBodyFit.h"
#include "ctMeshSequenceReader.h"
#include "ctMeshSequenceWriter.h"
#include "ctPatchCorrespondence.h"
#include "ctTemplateFit.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include <cstdio>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: " << argv[0] << " FRAMES GROUND_TRUTH OUT.pvd\n";
    return 1;
  }
  // Any error stops the program with the filter's message.
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(
      [](vtkObject*, unsigned long, void*, void* message)
      {
        std::cerr << "error: " << static_cast<const char*>(message) << "\n";
        std::exit(1);
      });

  vtkNew<ctMeshSequenceReader> frames;
  frames->SetFileName(argv[1]);
  vtkNew<ctMeshSequenceReader> truth;
  truth->SetFileName(argv[2]);

  // Stage 1: body model under the clothing, and its landmarks on every frame (output 1).
  vtkNew<ctBodyFit> body;
  body->SetInputConnection(frames->GetOutputPort(1));
  body->SetShapeFrames(4);
  // Stage 2: template frame chosen automatically, dense correspondences from geodesic patches.
  vtkNew<ctPatchCorrespondence> correspondence;
  correspondence->SetInputConnection(0, frames->GetOutputPort(1));
  correspondence->SetInputConnection(1, body->GetOutputPort(1));
  // Stage 3: the template deformed through the sequence.
  vtkNew<ctTemplateFit> fit;
  fit->SetInputConnection(0, frames->GetOutputPort(1));
  fit->SetInputConnection(1, correspondence->GetOutputPort(0));
  fit->SetInputConnection(2, body->GetOutputPort(1));
  fit->SetInputConnection(3, body->GetOutputPort(0)); // each frame starts from its body
  // Evaluation against the ground truth.
  vtkNew<ctAlignmentError> error;
  error->SetInputConnection(0, fit->GetOutputPort(0));
  error->SetInputConnection(1, truth->GetOutputPort(1));
  vtkNew<ctMeshSequenceWriter> writer;
  writer->SetInputConnection(error->GetOutputPort(0));
  writer->SetFileName(argv[3]);

  for (vtkObject* stage :
       std::initializer_list<vtkObject*>{frames, truth, body, correspondence, fit, error, writer})
    stage->AddObserver(vtkCommand::ErrorEvent, onError);
  writer->Write();

  vtkTable* table = error->GetFrameErrorOutput();
  std::printf("template frame %d\nframe  mean (cm)  within 10 cm\n",
              correspondence->GetChosenFrame());
  for (vtkIdType k = 0; k < table->GetNumberOfRows(); ++k)
    std::printf("%5lld  %9.2f  %11.1f%%\n", static_cast<long long>(k),
                100 * table->GetValueByName(k, "Mean").ToDouble(),
                100 * table->GetValueByName(k, "Within10cm").ToDouble());
  std::printf("wrote %d frames to %s\n", writer->GetNumberOfFramesWritten(), argv[3]);
  return 0;
}
