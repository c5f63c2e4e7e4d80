// ctModelChoice: the alignment kept among several made under other body models, by the rule of
// `clothtrack align --model A --model B`, from the template fits' per-frame tables; and clear
// errors for tables that cannot be judged.
#include "VtkTestUtil.h"
#include "ctModelChoice.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using clothtrack::test::ErrorWatch;

namespace
{
/// A per-frame table as ctTemplateFit writes it, with the two columns the choice reads.
vtkSmartPointer<vtkTable> frameTable(const std::vector<double>& stretch,
                                     const std::vector<double>& surfaceDistance)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  for (const auto& [name, values] :
       {std::pair{"Stretch", &stretch}, std::pair{"MeanSurfaceDistance", &surfaceDistance}})
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(name);
    for (double v : *values) column->InsertNextValue(v);
    table->AddColumn(column);
  }
  return table;
}

struct Choice
{
  vtkNew<ctModelChoice> filter;
  std::string error;

  int keep(const std::vector<vtkSmartPointer<vtkTable>>& tables)
  {
    for (const auto& t : tables) filter->AddInputDataObject(0, t);
    ErrorWatch watch(filter);
    filter->Update();
    error = watch.message;
    return filter->GetKeptAlignment();
  }
};
} // namespace

TEST(ModelChoiceFilter, KeepsALaterAlignmentOnlyWhenBetterOnBothFigures)
{
  // Means over the frames: first 0.040 / 2.0 mm; second 5 % and 10 % lower; third lower in
  // stretch only.
  const auto first = frameTable({0.03, 0.05}, {0.001, 0.003});
  const auto better = frameTable({0.038, 0.038}, {0.0018, 0.0018});
  const auto stretchOnly = frameTable({0.02, 0.02}, {0.0021, 0.0021});
  {
    Choice c;
    EXPECT_EQ(c.keep({first, better}), 1) << c.error;
    vtkTable* out = c.filter->GetOutput();
    ASSERT_EQ(out->GetNumberOfRows(), 2);
    EXPECT_NEAR(out->GetValueByName(0, "MeanStretch").ToDouble(), 0.04, 1e-15);
    EXPECT_NEAR(out->GetValueByName(0, "MeanSurfaceDistance").ToDouble(), 0.002, 1e-15);
    EXPECT_NEAR(out->GetValueByName(1, "MeanStretch").ToDouble(), 0.038, 1e-15);
    EXPECT_EQ(out->GetValueByName(0, "Kept").ToInt(), 0);
    EXPECT_EQ(out->GetValueByName(1, "Kept").ToInt(), 1);
    EXPECT_EQ(out->GetFieldData()->GetArray("KeptAlignment")->GetTuple1(0), 1.0);
  }
  {
    Choice c;
    EXPECT_EQ(c.keep({first, stretchOnly}), 0) << c.error;
  }
  {
    // The named order decides between two as good: the first stays.
    Choice c;
    EXPECT_EQ(c.keep({better, first}), 0) << c.error;
  }
  {
    // The stretch is 5 % lower: not enough under a 6 % margin.
    Choice c;
    c.filter->SetMargin(0.06);
    EXPECT_EQ(c.keep({first, better}), 0) << c.error;
  }
  {
    // Each is judged against the first: the third gains 6.25 and 12.5 %, the second 5 and 10 %,
    // so the third is kept although it beats the second by less than the margin.
    Choice c;
    const auto slightlyBetter = frameTable({0.0375}, {0.00175});
    EXPECT_EQ(c.keep({first, better, slightlyBetter}), 2) << c.error;
    vtkAbstractArray* criterion =
        c.filter->GetOutput()->GetFieldData()->GetAbstractArray("Criterion");
    ASSERT_NE(criterion, nullptr);
    EXPECT_NE(criterion->GetVariantValue(0).ToString().find("more than 2 %"), std::string::npos);
  }
}

TEST(ModelChoiceFilter, FramesWithoutAFigureAreLeftOut)
{
  Choice c;
  const auto first = frameTable({0.04, NAN}, {0.002, NAN});
  const auto better = frameTable({NAN, 0.03}, {0.001, 0.001});
  EXPECT_EQ(c.keep({first, better}), 1) << c.error;
  EXPECT_NEAR(c.filter->GetOutput()->GetValueByName(1, "MeanStretch").ToDouble(), 0.03, 1e-15);
}

TEST(ModelChoiceFilter, TablesThatCannotBeJudgedAreErrors)
{
  {
    Choice c;
    auto table = frameTable({0.04}, {0.002});
    table->RemoveColumnByName("Stretch");
    EXPECT_EQ(c.keep({frameTable({0.04}, {0.002}), table}), -1);
    EXPECT_NE(c.error.find("alignment 1 has no per-frame column Stretch"), std::string::npos)
        << c.error;
  }
  {
    Choice c;
    EXPECT_EQ(c.keep({frameTable({NAN, NAN}, {0.002, 0.002})}), -1);
    EXPECT_NE(c.error.find("alignment 0 has no frame with a finite Stretch"), std::string::npos)
        << c.error;
  }
  {
    vtkNew<ctModelChoice> filter;
    filter->SetMargin(2.0);
    EXPECT_EQ(filter->GetMargin(), 1.0);
  }
}
