#include "TestUtil.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FrameList.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace clothtrack;
using clothtrack::test::scratchDir;
using clothtrack::test::writeText;

TEST(FrameList, NaturalOrder)
{
  std::vector<std::string> names = {"mesh_10.obj", "mesh_2.obj", "mesh_1.obj", "mesh_001a.obj",
                                    "mesh_0100.obj"};
  std::sort(names.begin(), names.end(), naturalLess);
  EXPECT_EQ(names, (std::vector<std::string>{"mesh_1.obj", "mesh_001a.obj", "mesh_2.obj",
                                             "mesh_10.obj", "mesh_0100.obj"}));
  EXPECT_EQ(frameNumberFromName("/data/take3/mesh_0174.obj"), 174);
  EXPECT_EQ(frameNumberFromName("dancer_fr0005.obj"), 5);
  EXPECT_EQ(frameNumberFromName("mesh.obj"), -1);
}

TEST(FrameList, FolderPatternAndListFile)
{
  const std::string dir = scratchDir("framelist");
  for (const char* name : {"f_10.obj", "f_9.ply", "f_1.off", "notes.txt"})
    writeText(dir + "/" + name, "x");
  const auto folder = listFrames(dir);
  ASSERT_EQ(folder.size(), 3u);
  EXPECT_EQ(folder[0], dir + "/f_1.off");
  EXPECT_EQ(folder[1], dir + "/f_9.ply");
  EXPECT_EQ(folder[2], dir + "/f_10.obj");

  const auto pattern = listFrames(dir + "/f_*.o*");
  ASSERT_EQ(pattern.size(), 2u);
  EXPECT_EQ(pattern[0], dir + "/f_1.off");

  const std::string list = writeText(dir + "/frames.txt", "# my order\nf_10.obj\n\n  f_1.off  \n");
  const auto listed = listFrames(list);
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0], dir + "/f_10.obj");
  EXPECT_EQ(listed[1], dir + "/f_1.off");
}

TEST(FrameList, ClearErrors)
{
  const std::string dir = scratchDir("framelist-bad");
  EXPECT_THROW(listFrames(dir + "/nothing"), Error);
  EXPECT_THROW(listFrames(dir), Error); // empty folder
  EXPECT_THROW(listFrames(dir + "/*.obj"), Error);
  EXPECT_THROW(listFrames(""), Error);
  const std::string list = writeText(dir + "/list.txt", "frame.las\n");
  EXPECT_THROW(listFrames(list), Error);
}
