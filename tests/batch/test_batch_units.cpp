// Unit tests of the batch pieces that do not need a model: which files a batch
// finds and where their outputs go, the results log, and how a child's end is
// classified. End-to-end runs are in test_batch_cli.py and test_dask_batch.py.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "batch_child.hpp"
#include "batch_inputs.hpp"
#include "batch_results.hpp"
#include "cadmedial/errors.hpp"

namespace cadmedial {
namespace {
namespace fs = std::filesystem;

class BatchUnits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cadmedial_batch_units_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path touch(const fs::path& rel, const std::string& content = "x") {
    const fs::path p = dir_ / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << content;
    return p;
  }
  static std::vector<std::string> outputsOf(const std::vector<BatchInput>& inputs) {
    std::vector<std::string> out;
    for (const BatchInput& in : inputs) out.push_back(in.output);
    return out;
  }
  static ExitCode usageCode(const std::vector<std::string>& args, const std::string& skip = "") {
    try {
      collectBatchInputs(args, skip);
    } catch (const InputError& e) {
      return e.code();
    }
    return kExitOk;
  }
  fs::path dir_;
};

TEST_F(BatchUnits, FolderIsRecursiveSortedCaseInsensitiveAndSkipsHiddenAndOutput) {
  for (const char* f : {"b.STEP", "a/x.stp", "a/y.Igs", "a/z.iges", "c.brep", "notes.txt", "d.obj", ".hidden/h.step",
                        "out/res/q.step", "a/.h.step"})
    touch(f);
  const auto inputs = collectBatchInputs({dir_.string()}, (dir_ / "out").string());
  EXPECT_EQ(outputsOf(inputs), (std::vector<std::string>{"a/x.stp", "a/y.Igs", "a/z.iges", "b.STEP", "c.brep"}));
  EXPECT_EQ(inputs[0].path, (dir_ / "a/x.stp").string());
}

TEST_F(BatchUnits, ManifestLinesResolveAgainstTheManifestFolder) {
  touch("m/sub/p.step");
  touch("m/folder/f1.step");
  const fs::path elsewhere = touch("other/q.step");
  touch("m/list.lst", "# parts\n\nsub/p.step\r\n  folder  \n" + elsewhere.string() + "\nmissing.step\n");
  const auto inputs = collectBatchInputs({(dir_ / "m/list.lst").string()}, "");
  ASSERT_EQ(inputs.size(), 4u);
  EXPECT_EQ(inputs[0].output, "sub/p.step");
  EXPECT_EQ(inputs[1].output, "f1.step");                         // a folder line: relative to that folder
  EXPECT_EQ(inputs[2].output, elsewhere.relative_path().string());  // outside the base: absolute minus '/'
  EXPECT_EQ(inputs[3].output, "missing.step");                    // kept: `run` records the error
  EXPECT_EQ(inputs[3].path, (dir_ / "m/missing.step").string());
}

TEST_F(BatchUnits, AtPrefixReadsAnyFileAsManifestAndRepeatsAreDropped) {
  const fs::path p = touch("p.step");
  touch("names", "p.step\n./p.step\n");
  const auto inputs = collectBatchInputs({"@" + (dir_ / "names").string(), p.string()}, "");
  ASSERT_EQ(inputs.size(), 1u);
  EXPECT_EQ(inputs[0].output, "p.step");
}

TEST_F(BatchUnits, ClashingOutputFoldersMissingManifestAndNoFilesAreUsageErrors) {
  touch("one/x.step");
  touch("two/x.step");
  EXPECT_EQ(usageCode({(dir_ / "one").string(), (dir_ / "two").string()}), kExitUsage);
  EXPECT_EQ(usageCode({(dir_ / "nope.txt").string()}), kExitUsage);
  fs::create_directories(dir_ / "empty");
  EXPECT_EQ(usageCode({(dir_ / "empty").string()}), kExitUsage);
  EXPECT_EQ(usageCode({(dir_ / "one").string()}), kExitOk);
}

TEST_F(BatchUnits, LastRecordWinsAndATornLineIsSkippedAndRepaired) {
  const std::string path = (dir_ / "results.jsonl").string();
  std::ofstream(path) << R"({"output":"a.step","status":"error"})" << "\n"
                      << R"({"output":"a.step","status":"ok","solids":[{"solid":0}]})" << "\n"
                      << R"({"output":"b.step","sta)";
  auto last = readLastRecords(path);
  ASSERT_EQ(last.size(), 1u);
  EXPECT_EQ(last["a.step"].status, "ok");
  EXPECT_EQ(last["a.step"].solids, std::vector<int>{0});
  {
    ResultsLog log(path);
    FileResult r;
    r.path = "/x/b.step";
    r.output = "b.step";
    r.status = FileStatus::Timeout;
    log.append(toJson(r));
  }
  last = readLastRecords(path);
  ASSERT_EQ(last.size(), 2u);
  EXPECT_EQ(last["b.step"].status, "timeout");
  EXPECT_EQ(last["b.step"].path, "/x/b.step");
  std::ifstream in(path);
  std::string line, lastLine;
  while (std::getline(in, line)) lastLine = line;
  EXPECT_EQ(lastLine.rfind(R"({"path":"/x/b.step","output":"b.step","status":"timeout","exit_code":null,)", 0), 0u)
      << lastLine;
}

TEST_F(BatchUnits, OutputsCompleteNeedsEveryFileOfEverySolid) {
  const LastRecord record{"/m.step", "ok", {0, 1}, {false, true}};
  for (const char* f : {"medial.ply", "medial.obj", "medial.ma", "summary.json"}) {
    touch(std::string("o/solid_0/") + f);
    touch(std::string("o/solid_1/") + f);
  }
  const std::string folder = (dir_ / "o").string();
  EXPECT_FALSE(outputsComplete(record, folder));  // solid 1 was evaluated but eval.json is gone
  touch("o/solid_1/eval.json");
  EXPECT_TRUE(outputsComplete(record, folder));
  fs::remove(dir_ / "o/solid_0/medial.ma");
  EXPECT_FALSE(outputsComplete(record, folder));
  EXPECT_FALSE(outputsComplete(LastRecord{"/m.step", "error", {}, {}}, folder));
}

TEST_F(BatchUnits, SolidSummariesCarryCountsTimesAndEvalHeadline) {
  touch("o/solid_0/summary.json", R"({"counts":{"samples":7},"seconds":{"read":0.5},"topology":{"beta0":1}})");
  touch("o/solid_0/eval.json", R"({"inside":{"share":0.99},"pass":{"all":true}})");
  touch("o/solid_1/summary.json", R"({"counts":{"samples":9}})");
  const nlohmann::json solids = readSolidSummaries((dir_ / "o").string());
  ASSERT_EQ(solids.size(), 2u);
  EXPECT_EQ(solids[0]["counts"]["samples"], 7);
  EXPECT_EQ(solids[0]["seconds"]["read"], 0.5);
  EXPECT_EQ(solids[0]["eval"]["inside_share"], 0.99);
  EXPECT_EQ(solids[0]["eval"]["pass"], true);
  EXPECT_TRUE(solids[0]["eval"]["coverage_share"].is_null());
  EXPECT_FALSE(solids[1].contains("eval"));
}

// Runs `sh -c script` through startChild and returns how it ended.
struct Ended {
  ChildExit exit;
  std::string stderrText;
};
Ended runShell(const fs::path& dir, const std::string& script, double maxMemoryGiB = 0) {
  const std::string errPath = (dir / "child.stderr").string();
  const pid_t pid = startChild("/bin/sh", {"-c", script}, errPath, maxMemoryGiB);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  std::ifstream in(errPath);
  return {decodeChildExit(status, usage.ru_maxrss),
          std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())};
}

TEST_F(BatchUnits, ChildExitCodesSignalsAndMessagesAreClassified) {
  Ended e = runShell(dir_, "echo 'warning: w' >&2; echo 'error: m.step: no closed solid' >&2; echo tail >&2; exit 4");
  EXPECT_EQ(e.exit.exitCode, 4);
  EXPECT_EQ(classifyChild(e.exit, false, e.stderrText), FileStatus::Error);
  EXPECT_EQ(describeFailure(FileStatus::Error, e.exit, 0, e.stderrText), "m.step: no closed solid");

  e = runShell(dir_, "kill -SEGV $$");
  EXPECT_EQ(e.exit.signal, SIGSEGV);
  EXPECT_EQ(classifyChild(e.exit, false, e.stderrText), FileStatus::Crash);
  EXPECT_EQ(describeFailure(FileStatus::Crash, e.exit, 0, e.stderrText), "killed by SIGSEGV");

  e = runShell(dir_, "echo \"terminate called after throwing an instance of 'std::bad_alloc'\" >&2; kill -ABRT $$");
  EXPECT_EQ(classifyChild(e.exit, false, e.stderrText), FileStatus::Oom);
  e = runShell(dir_, "kill -KILL $$");  // nobody in the batch sent it: the kernel's OOM killer
  EXPECT_EQ(classifyChild(e.exit, false, e.stderrText), FileStatus::Oom);
  EXPECT_EQ(classifyChild(e.exit, true, e.stderrText), FileStatus::Timeout);

  e = runShell(dir_, "exit 0");
  EXPECT_EQ(classifyChild(e.exit, false, e.stderrText), FileStatus::Ok);
  EXPECT_GT(e.exit.peakRssMiB, 0);
}

TEST_F(BatchUnits, ChildLeadsItsOwnProcessGroupAndGetsTheMemoryLimit) {
  const Ended e = runShell(dir_, "ps -o pgid= -p $$ | tr -d ' ' >&2; echo $$ >&2; ulimit -v >&2", 0.5);
  std::istringstream lines(e.stderrText);
  std::string pgid, pid, limitKiB;
  lines >> pgid >> pid >> limitKiB;
  EXPECT_EQ(pgid, pid);
  EXPECT_EQ(limitKiB, std::to_string(512 * 1024));
}

TEST_F(BatchUnits, ErrorLineIsShortAndSingle) {
  EXPECT_EQ(errorLineOf(""), "");
  EXPECT_EQ(errorLineOf("a\nb\n\n"), "b");
  EXPECT_EQ(errorLineOf("error: one\nerror: two\r\n"), "two");
  EXPECT_EQ(errorLineOf(std::string(2000, 'x')).size(), 500u);
}

}  // namespace
}  // namespace cadmedial
