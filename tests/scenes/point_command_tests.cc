// `vulnus point`: the driver command produces the documented CSV for a deck's material, the
// matrix fails at the isochoric fiber stretch 1.3247 (root of l^3 - l - 1), and bad input
// stops with exit status 2 and a message naming what is wrong.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::string source_dir()
{
  const char* dir = std::getenv("VULNUS_SOURCE_DIR");
  return dir ? dir : VULNUS_DEFAULT_SOURCE_DIR;
}

/// Runs a shell command; returns exit status and combined output.
std::pair<int, std::string> run(const std::string& command)
{
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe))
    output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string vulnus()
{
  const char* binary = std::getenv("VULNUS_BINARY");
  return binary ? binary : VULNUS_DEFAULT_BINARY;
}
} // namespace

TEST(PointCommand, UniaxialFiberPathOfThePaperTissue)
{
  const std::string out = ::testing::TempDir() + "point_uniaxial.csv";
  const auto [status, text] =
    run(vulnus() + " point " + source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm" +
        " --material tissue --path uniaxial-fiber --max 1.4 --steps 200 --output " + out);
  ASSERT_EQ(status, 0) << text;
  std::ifstream in(out);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "step,J,fiber_stretch,sigma_xx,sigma_yy,sigma_zz,sigma_xy,sigma_yz,sigma_xz,"
                    "energy_density,failure");
  std::string line;
  double first_failed_stretch = 0.0;
  int n_rows = 0;
  while (std::getline(in, line))
  {
    std::stringstream row(line);
    std::vector<double> values;
    std::string cell;
    while (std::getline(row, cell, ','))
      values.push_back(std::stod(cell));
    ASSERT_EQ(values.size(), 11u);
    ++n_rows;
    EXPECT_NEAR(values[1], 1.0, 1e-12); // isochoric path
    if (values[10] != 0 && first_failed_stretch == 0.0)
      first_failed_stretch = values[2];
  }
  EXPECT_EQ(n_rows, 201);
  // Steps of 0.002 in stretch: the first failed row lies within one step above 1.324718.
  EXPECT_GT(first_failed_stretch, 1.324718);
  EXPECT_LT(first_failed_stretch, 1.324718 + 0.0021);
}

TEST(PointCommand, BadInputGivesExitStatusTwoAndAMessage)
{
  const std::string deck = source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm";
  const std::string out = ::testing::TempDir() + "point_bad.csv";
  auto [status, text] = run(vulnus() + " point " + deck + " --material tisue --path uniaxial-fiber --max 1.2 --steps 5 --output " + out);
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("no material 'tisue'"), std::string::npos) << text;

  std::tie(status, text) = run(vulnus() + " point " + deck + " --material tissue --path uniaxial-fiber --max 1.2 --output " + out);
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("--steps"), std::string::npos) << text;

  const std::string bad_csv = ::testing::TempDir() + "bad_deformation.csv";
  std::ofstream(bad_csv) << "F11,F12,F13,F21,F22,F23,F31,F32,F33\n1,0,0,0,1,0,0,0,x\n";
  std::tie(status, text) = run(vulnus() + " point " + deck + " --material tissue --deformation " + bad_csv + " --output " + out);
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("line 2"), std::string::npos) << text;
}
