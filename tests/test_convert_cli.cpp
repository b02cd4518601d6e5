// End to end through the contactbench binary for instrument files (docs/formats.md): stats says which
// channel, fill and levelling were applied; convert writes .x3p, .npy and the project's format losslessly.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "cli_runner.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

using testing::kFormatSamples;

using testing::CommandResult;
using testing::slurp;

class ConvertCli : public testing::CliTest {
 protected:
  ConvertCli() : CliTest("contactbench_convert_cli_") {}
};

std::string json_text(const std::string& json, const std::string& key) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + key + "\": (\"[^\"]*\"|[-+0-9.eE]+)")))
    throw std::runtime_error("no key " + key + " in " + json);
  return match[1];
}

TEST_F(ConvertCli, StatsReportsChannelFillAndLevelling) {
  const CommandResult refused = run("stats " + (kFormatSamples / "opd-1.opd").string());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("opd-1.opd: 116 of 307200 points"), std::string::npos) << refused.err;
  const CommandResult filled =
      run("stats " + (kFormatSamples / "opd-1.opd").string() + " --fill harmonic --level plane");
  ASSERT_EQ(filled.status, 0) << filled.err;
  EXPECT_EQ(json_text(filled.out, "format"), "\"wyko\"");
  EXPECT_EQ(json_text(filled.out, "invalid_points_filled"), "116");
  EXPECT_EQ(json_text(filled.out, "fill"), "\"harmonic\"");
  EXPECT_EQ(json_text(filled.out, "level"), "\"plane\"");
  // After plane levelling the mean is zero to round-off of 307200 heights of ~1e-8 m.
  EXPECT_LT(std::abs(std::stod(json_text(filled.out, "mean"))), 1e-20);
  const CommandResult channel = run("stats " + (kFormatSamples / "di-3.di").string() + " --channel Height");
  ASSERT_EQ(channel.status, 0) << channel.err;
  EXPECT_EQ(json_text(channel.out, "channel"), "\"Height\"");
  EXPECT_EQ(json_text(channel.out, "level"), "\"none\"");
  const CommandResult unknown = run("stats " + (kFormatSamples / "di-3.di").string() + " --channel Nope");
  EXPECT_EQ(unknown.status, 1);
  EXPECT_NE(unknown.err.find("unknown channel 'Nope'; the file's channels: 0 'ZSensor'"), std::string::npos)
      << unknown.err;
  const CommandResult bad_level = run("stats " + (kFormatSamples / "di-3.di").string() + " --level tilt");
  EXPECT_NE(bad_level.status, 0);
  EXPECT_NE(bad_level.err.find("--level"), std::string::npos) << bad_level.err;
}

TEST_F(ConvertCli, ConvertWritesX3pNpyAndTheProjectFormatLosslessly) {
  const fs::path source = kFormatSamples / "metropro-1.dat";
  const CommandResult original = run("stats " + source.string());
  ASSERT_EQ(original.status, 0) << original.err;
  for (const std::string name : {"m.x3p", "m.npy", "m.txt"}) {
    const fs::path out = folder_ / name;
    const CommandResult converted = run("convert " + source.string() + " " + out.string());
    ASSERT_EQ(converted.status, 0) << converted.err;
    const std::string size = name == "m.npy" ? " --size 7.028812979115173e-04" : "";
    const CommandResult copy = run("stats " + out.string() + size);
    ASSERT_EQ(copy.status, 0) << copy.err;
    // The same heights: the same shortest-decimal mean and Sq, printed by the same code.
    for (const char* key : {"nx", "ny", "mean", "sq"})
      EXPECT_EQ(json_text(copy.out, key), json_text(original.out, key)) << name << " " << key;
  }
  const CommandResult bad =
      run("convert " + (kFormatSamples / "wrongnpyfile.npy").string() + " " + (folder_ / "x.x3p").string());
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("wrong magic"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(folder_ / "x.x3p"));
}

}  // namespace
}  // namespace contactbench
