#include <clothtrack/base/Error.h>
#include <clothtrack/eval/MarkerError.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace clothtrack;

namespace
{
std::string writeFile(const std::string& name, const std::string& text)
{
  const std::string dir = CLOTHTRACK_TEST_TMP "/markers";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}
} // namespace

TEST(MarkerError, ReadsTrajectoriesAndMeasuresAtTheNearestTemplateVertex)
{
  const std::string path = writeFile("ok.csv", "frame,time,marker,x,y,z\n"
                                               "0,0.0,knee,0.1,0,0\n"
                                               "0,0.0,head,0,1.9,0\n"
                                               "1,0.04,knee,0.1,0,0.5\n"
                                               "2,0.08,knee,0.1,0,1.0\n"
                                               "2,0.08,head,0,1.9,1.0\n");
  const MarkerTrajectories markers = readMarkersCsv(path);
  ASSERT_EQ(markers.names, (std::vector<std::string>{"knee", "head"}));
  ASSERT_EQ(markers.numFrames(), 3);
  EXPECT_TRUE(std::isnan(markers.positions[1](1, 0))); // head missing in frame 1

  Points templ(3, 3);
  templ << 0, 0, 0, 0, 2, 0, 5, 5, 5;
  const std::vector<int> vertices = nearestTemplateVertices(templ, markers.positions[0]);
  EXPECT_EQ(vertices, (std::vector<int>{0, 1}));

  // The template moves 0.5 per frame along z; the knee marker follows, the head lags by 0.2.
  std::vector<Points> aligned;
  for (int k = 0; k < 3; ++k)
  {
    Points p = templ;
    p.col(2).array() += 0.5 * k;
    aligned.push_back(p);
  }
  aligned[2](1, 2) -= 0.2;
  const Eigen::MatrixXd errors = markerErrors(aligned, markers, vertices);
  EXPECT_NEAR(errors(0, 0), 0.1, 1e-12);
  EXPECT_NEAR(errors(1, 0), 0.1, 1e-12);
  EXPECT_TRUE(std::isnan(errors(1, 1)));
  EXPECT_NEAR(errors(2, 1), std::hypot(0.1, 0.2), 1e-12);

  const SequenceErrors summary = markerSequenceErrors(errors, 0);
  EXPECT_EQ(summary.pooled.count, 3); // frames 1 and 2; head missing in 1
  EXPECT_NEAR(summary.pooled.mean, (0.1 + 0.1 + std::hypot(0.1, 0.2)) / 3, 1e-12);
  EXPECT_EQ(summary.worstFrame, 2);

  // Fewer aligned frames than marker frames: an error that says so.
  aligned.pop_back();
  EXPECT_THROW(markerErrors(aligned, markers, vertices), Error);
}

TEST(MarkerError, BadFilesNameTheFileAndLine)
{
  auto message = [](const std::string& path)
  {
    try
    {
      readMarkersCsv(path);
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(CLOTHTRACK_TEST_TMP "/markers/none.csv").find("none.csv: cannot open"),
            std::string::npos);
  EXPECT_NE(message(writeFile("empty.csv", "")).find("empty marker file"), std::string::npos);
  EXPECT_NE(message(writeFile("header.csv", "frame,time,marker,x,y,z\n")).find("no marker rows"),
            std::string::npos);
  EXPECT_NE(message(writeFile("bad.csv", "frame,time,marker,x,y,z\n0,0,a,1,2,3\n1,0,a,1,x\n"))
                .find("bad.csv:3: expected frame,time,marker,x,y,z"),
            std::string::npos);
  EXPECT_NE(message(writeFile("nan.csv", "frame,time,marker,x,y,z\n0,0,a,nan,2,3\n"))
                .find("nan.csv:2: marker position is not finite"),
            std::string::npos);
}
