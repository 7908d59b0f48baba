// SPDX-License-Identifier: MIT
// frusta-bake run as a process, as a user or a build script runs it.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "corpus_fixture.h"
#include "core/error.h"
#include "spheretree/tree_file.h"

namespace {

struct Process {
  int code;
  std::string out;
};

Process run(const std::string& arguments) {
  const std::string command = std::string(FRUSTA_BAKE_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

double figure(const std::string& json, const char* key) {
  const std::regex pattern(std::string("\"") + key + "\": ([0-9.eE+-]+)");
  std::smatch m;
  return std::regex_search(json, m, pattern) ? std::stod(m[1]) : -1.0;
}

const std::string kObjects = FRUSTA_SAMPLE_OBJECTS_DIR;

TEST(FrustaBakeCli, BakesASampleWithinOneMillimetreAndSaysSoInJson) {
  const std::string out = ::testing::TempDir() + "mug.frtree";
  const Process r = run("--max-error 1 --json -o " + out + " " + kObjects + "/mug.glb");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("\"target_met\": true"), std::string::npos) << r.out;
  EXPECT_GT(figure(r.out, "uncovered_error_mm"), 0.0);
  EXPECT_LE(figure(r.out, "uncovered_error_mm"), 1.0);
  EXPECT_LE(figure(r.out, "protruding_error_mm"), 1.0);
  EXPECT_GE(figure(r.out, "error_samples"), 100000);
  EXPECT_GT(figure(r.out, "leaves"), 100);
  // what it wrote loads, and carries the same figures
  frusta::TreeFile file;
  ASSERT_EQ(frusta::load_tree_file(out, &file), FRUSTA_OK) << frusta::last_error_message();
  EXPECT_NEAR(file.bake.uncovered_error * 1e3, figure(r.out, "uncovered_error_mm"), 1e-4);
  EXPECT_EQ(static_cast<double>(file.tree.leaves.size()), figure(r.out, "leaves"));
}

TEST(FrustaBakeCli, ReproducibleBakesWriteTheSameBytes) {
  // the sample objects are baked so: the Unity sample carries byte-identical copies
  const auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string a = ::testing::TempDir() + "repro_a.frtree", b = ::testing::TempDir() + "repro_b.frtree";
  for (const std::string& out : {a, b}) {
    const Process r = run("--reproducible --json -o " + out + " " + kObjects + "/box.glb");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_GT(figure(r.out, "bake_seconds"), 0.0);  // still reported, only not stored
  }
  EXPECT_EQ(bytes(a), bytes(b));
  frusta::TreeFile file;
  ASSERT_EQ(frusta::load_tree_file(a, &file), FRUSTA_OK) << frusta::last_error_message();
  EXPECT_EQ(file.bake.bake_seconds, 0.0);
}

TEST(FrustaBakeCli, HumanSummaryNamesBothFigures) {
  const Process r = run("-o " + ::testing::TempDir() + "box.frtree " + kObjects + "/box.glb");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("uncovered"), std::string::npos);
  EXPECT_NE(r.out.find("protruding"), std::string::npos);
  EXPECT_EQ(r.out.find('\r'), std::string::npos);  // no progress bar into a pipe
}

TEST(FrustaBakeCli, ExitCodesSeparateTheFailures) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("--max-error").code, 2);
  EXPECT_EQ(run("--max-error lots x.glb").code, 2);
  EXPECT_EQ(run("--frobnicate 3 x.glb").code, 2);
  const Process missing = run("/nonexistent/x.glb");
  EXPECT_EQ(missing.code, 3);
  EXPECT_NE(missing.out.find("/nonexistent/x.glb"), std::string::npos);
  const std::string junk = ::testing::TempDir() + "junk.gltf";
  std::ofstream(junk) << "not gltf";
  EXPECT_EQ(run(junk).code, 3);
  EXPECT_EQ(
      run("--branching 99 " + kObjects + "/box.glb -o " + ::testing::TempDir() + "b.frtree").code,
      2);
  const Process deep = run("--max-depth 1 --branching 2 " + kObjects + "/box.glb -o " +
                           ::testing::TempDir() + "d.frtree");
  EXPECT_EQ(deep.code, 4) << deep.out;
  EXPECT_NE(deep.out.find("max_depth is 1"), std::string::npos) << deep.out;
  EXPECT_EQ(run("-o /nonexistent/dir/x.frtree " + kObjects + "/box.glb").code, 5);
  const Process budget = run("--max-leaves 20 -o " + ::testing::TempDir() + "c.frtree " + kObjects + "/ball.glb");
  EXPECT_EQ(budget.code, 6) << budget.out;
  EXPECT_NE(budget.out.find("NOT met"), std::string::npos) << budget.out;
  const Process help = run("--help");
  EXPECT_EQ(help.code, 0);
  for (const char* option : {"--max-error", "--max-leaves", "--branching", "--max-depth", "--samples",
                             "--seed", "--json", "--output", "--quiet"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

// Issue 16: every option's range is checked where it is parsed, integers as
// integers; out of range is a usage error (2) naming the option, never a bake that
// fails (4) or aborts in Embree (134), nor a cast of 1e30 to an integer
TEST(FrustaBakeCli, OptionsOutOfRangeAreUsageErrorsNamingTheOption) {
  struct Bad {
    const char* arguments;
    const char* fragment;
  };
  const Bad cases[] = {{"--max-error 1e300", "--max-error 1e300"},
                       {"--max-error 1001", "--max-error"},
                       {"--max-error 0.001", "--max-error"},
                       {"--max-error 0", "--max-error"},
                       {"--max-error -1", "--max-error"},
                       {"--max-error nan", "--max-error"},
                       {"--max-error inf", "--max-error"},
                       {"--branching 99", "--branching 99"},
                       {"--branching 1", "--branching"},
                       {"--branching 1e30", "--branching"},
                       {"--branching nan", "--branching"},
                       {"--branching 2.5", "--branching"},
                       {"--branching 4294967298", "4294967298"},
                       {"--max-leaves 0", "--max-leaves"},
                       {"--max-leaves 16777217", "--max-leaves"},
                       {"--max-leaves 1e30", "--max-leaves"},
                       {"--max-leaves 99999999999999999999", "--max-leaves"},
                       {"--max-depth 41", "--max-depth"},
                       {"--max-depth -1", "--max-depth"},
                       {"--samples 999", "--samples"},
                       {"--samples 10000001", "--samples"},
                       {"--samples 1e30", "--samples"},
                       {"--samples nan", "--samples"},
                       {"--seed -1", "--seed"},
                       {"--seed 1e3", "--seed"},
                       {"--seed 18446744073709551616", "--seed"}};
  for (const Bad& c : cases) {
    const Process r = run(std::string(c.arguments) + " -o " + ::testing::TempDir() + "r.frtree " +
                          kObjects + "/box.glb");
    EXPECT_EQ(r.code, 2) << c.arguments << ": " << r.out;
    EXPECT_NE(r.out.find(c.fragment), std::string::npos) << c.arguments << ": " << r.out;
  }
  // the edges themselves are taken: the largest target on a small box, the largest seed
  const Process edge = run("--max-error 1000 --samples 1000 --seed 18446744073709551615 -o " +
                           ::testing::TempDir() + "edge.frtree " + kObjects + "/box.glb");
  EXPECT_TRUE(edge.code == 0 || edge.code == 6) << edge.out;
}

// The hostile glTF corpus through the CLI (issue 16): no crash, hang or abort, exit 3
// with a message naming the file, nothing beside the input's folder opened; the files
// that load bake.
TEST(FrustaBakeCli, TheHostileCorpusEndsInExitCode3NamingTheFile) {
  frusta::corpus::Folder folder;
  frusta::corpus::OpenWatch outside(folder.root());
  for (const frusta::corpus::Case& c : frusta::corpus::Folder::all_cases()) {
    const std::string path = folder.in(c.file);
    const Process r =
        run("-q --max-error 2 --samples 1000 -o " + folder.in("out.frtree") + " " + path);
    if (c.result == "FRUSTA_OK") {
      EXPECT_TRUE(r.code == 0 || r.code == 6) << c.file << ": " << r.out;
    } else {
      EXPECT_EQ(r.code, 3) << c.file << ": " << r.out;
      EXPECT_NE(r.out.find(path), std::string::npos) << c.file << ": " << r.out;
      EXPECT_NE(r.out.find(c.fragment), std::string::npos) << c.file << ": " << r.out;
    }
    for (const std::string& name : outside.take())
      ADD_FAILURE() << c.file << ": " << name << " beside the input's folder was opened";
  }
  const Process fifo = run("-q " + folder.in("fifo.bin"));
  EXPECT_EQ(fifo.code, 3) << fifo.out;
  const Process zero = run("-q -o " + folder.in("z.frtree") + " /dev/zero");
  EXPECT_EQ(zero.code, 3) << zero.out;
  EXPECT_NE(zero.out.find("not a regular file"), std::string::npos) << zero.out;
}

}  // namespace
