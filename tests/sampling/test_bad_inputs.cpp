// Bad files give the documented error (library: InputError with a code; CLI:
// one line on stderr and the exit code), never a crash or a partial output.
#include <gtest/gtest.h>

#include <algorithm>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Bnd_Box.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_MakeThickSolid.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {
namespace fs = std::filesystem;

class BadInputs : public test::ScratchDirTest {
 protected:
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  std::string truncatedBox() {
    std::ifstream in(std::string(CADMEDIAL_MODELS_DIR) + "/box.step", std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return write("truncated.step", all.substr(0, all.size() / 2));
  }
  // Runs `cadmedial COMMAND 'MODEL' ARGS -o 'OUT'` (at most 120 s); returns
  // its exit code (-1 if it did not exit) and leaves stderr in `err`.
  int runCommand(const std::string& command, const std::string& model, const std::string& args,
                 const std::string& out, std::string& err) {
    const fs::path errFile = dir_ / "stderr.txt";
    const std::string cmd = "timeout 120 " + std::string(CADMEDIAL_CLI) + " " + command + " '" + model + "' " + args +
                            " -o '" + out + "' >/dev/null 2>'" + errFile.string() + "'";
    const int status = std::system(cmd.c_str());
    std::ifstream in(errFile);
    err.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  // `cadmedial sample MODEL`.
  int runCli(const std::string& model, std::string& err) {
    return runCommand("sample", model, "", (dir_ / "out").string(), err);
  }
  // loadModel(path)'s refusal: its code and message (0 and "" with a test
  // failure when it loads).
  static std::pair<int, std::string> refusalOf(const std::string& path) {
    try {
      loadModel(path);
    } catch (const InputError& e) {
      return {e.code(), e.what()};
    }
    ADD_FAILURE() << path << " should not load";
    return {0, ""};
  }
  static ExitCode codeOf(const std::string& path) {
    try {
      loadModel(path);
    } catch (const InputError& e) {
      return e.code();
    }
    return kExitOk;
  }
};

TEST_F(BadInputs, MissingEmptyTextAndTruncatedFilesAreUnreadable) {
  EXPECT_EQ(codeOf((dir_ / "nope.step").string()), kExitUnreadableInput);
  EXPECT_EQ(codeOf(write("empty.step", "")), kExitUnreadableInput);
  EXPECT_EQ(codeOf(write("text.step", "this is not a STEP file\njust text\n")), kExitUnreadableInput);
  EXPECT_EQ(codeOf(write("text.iges", "not IGES either\n")), kExitUnreadableInput);
  EXPECT_EQ(codeOf(write("text.brep", "not BREP\n")), kExitUnreadableInput);
  EXPECT_EQ(codeOf(write("model.obj", "v 0 0 0\n")), kExitUnreadableInput);
  EXPECT_EQ(codeOf(dir_.string()), kExitUnreadableInput);
  const ExitCode truncated = codeOf(truncatedBox());
  EXPECT_TRUE(truncated == kExitUnreadableInput || truncated == kExitNoSolid) << truncated;
}

// One misspelt entity name (CARTESIAN_PINT for the box's first point, which
// its placement refers to) made STEPControl_Reader dereference a null handle:
// SIGSEGV. Now the translator's crash is caught and the file is unreadable,
// in the library and in the CLI, and the process lives on to read the next.
TEST_F(BadInputs, AMisspeltEntityIsAnErrorNotACrash) {
  std::ifstream in(std::string(CADMEDIAL_MODELS_DIR) + "/box.step", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = all.find("CARTESIAN_POINT");
  ASSERT_NE(at, std::string::npos);
  const std::string misspelt = write("misspelt.step", all.substr(0, at) + "CARTESIAN_PINT" + all.substr(at + 15));
  const auto [code, message] = refusalOf(misspelt);
  EXPECT_EQ(code, kExitUnreadableInput);
  EXPECT_NE(message.find("could not be translated"), std::string::npos) << message;
  EXPECT_EQ(loadModel(write("box.step", all)).solids.size(), 1u);  // the process reads on
  std::string err;
  EXPECT_EQ(runCli(misspelt, err), kExitUnreadableInput) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "solid_0" / "samples.ply"));
}

// A solid reaching past OCCT's infinity (2e100; a STEP point misprinted as
// 1e300 gave one) is skipped with a warning, and a file of nothing else is
// unreadable at once: OCCT's point-in-face tests on such a solid had not
// finished after 5 minutes.
TEST_F(BadInputs, ASolidReachingInfinityIsSkippedNotRunForever) {
  // OCCT builds no such solid itself: one vertex of a box's BREP text is moved.
  auto withAVertexAt1e300 = [](const TopoDS_Shape& shape) {
    std::ostringstream out;
    BRepTools::Write(shape, out);
    std::string text = out.str();
    const std::size_t vertex = text.find("\nVe\n");
    const std::size_t point = text.find('\n', vertex + 4) + 1;  // "\nVe\n", the tolerance line, the point
    return text.replace(point, text.find('\n', point) - point, "1e+300 0 0");
  };
  const std::string endless = write("endless.brep", withAVertexAt1e300(BRepPrimAPI_MakeBox(10, 10, 10).Shape()));
  const auto [code, message] = refusalOf(endless);
  EXPECT_EQ(code, kExitUnreadableInput);
  EXPECT_NE(message.find("2e100"), std::string::npos) << message;
  std::string err;
  EXPECT_EQ(runCli(endless, err), kExitUnreadableInput) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;

  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, BRepPrimAPI_MakeBox(10, 10, 10).Shape());
  builder.Add(both, BRepPrimAPI_MakeBox(gp_Pnt(20, 0, 0), 10, 10, 10).Shape());
  const LoadedModel one = loadModel(write("one_endless.brep", withAVertexAt1e300(both)));
  EXPECT_EQ(one.solids.size(), 1u);
  EXPECT_NE(test::warningContaining(one.warnings, "skipped: it reaches coordinates beyond 2e100"), "");
}

TEST_F(BadInputs, ExtensionIsCaseInsensitive) {
  std::ifstream in(std::string(CADMEDIAL_MODELS_DIR) + "/box.step", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(loadModel(write("BOX.STEP", all)).solids.size(), 1u);
  EXPECT_EQ(loadModel(write("box.Stp", all)).solids.size(), 1u);
}

TEST_F(BadInputs, CliPrintsOneLineAndTheDocumentedExitCode) {
  std::string err;
  EXPECT_EQ(runCli((dir_ / "missing.step").string(), err), kExitUnreadableInput);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("no such file"), std::string::npos) << err;
  EXPECT_EQ(runCli(write("empty.stp", ""), err), kExitUnreadableInput);
  EXPECT_EQ(runCli(write("text.step", "hello\n"), err), kExitUnreadableInput);
  const int truncated = runCli(truncatedBox(), err);
  EXPECT_TRUE(truncated == kExitUnreadableInput || truncated == kExitNoSolid) << truncated << err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "solid_0" / "samples.ply"));
}

TEST_F(BadInputs, ShellOnlyAndSurfaceOnlyFilesSayWhatTheyHold) {
  const std::string dir = test::publicModelsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/models/public not present";
  // 213 trimmed surfaces that do not close up even when sewn.
  try {
    loadModel(dir + "/bearing.iges");
    ADD_FAILURE() << "bearing.iges should have no closed solid";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), kExitNoSolid);
    EXPECT_NE(std::string(e.what()).find("213 face(s)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("left open"), std::string::npos) << e.what();
  }
  std::string err;
  EXPECT_EQ(runCli(dir + "/bearing.iges", err), kExitNoSolid) << err;

  // 53 single-face open shells that sew into one closed bevel gear: every
  // face kept (the solid's area is the faces'), valid, matter inside.
  const LoadedModel gear = loadModel(dir + "/belever_gear.step");
  EXPECT_EQ(gear.census.solids, 0);
  ASSERT_EQ(gear.solids.size(), 1u);
  EXPECT_TRUE(BRepCheck_Analyzer(gear.solids[0]).IsValid());
  double facesArea = 0;
  for (TopExp_Explorer f(gear.shape, TopAbs_FACE); f.More(); f.Next()) {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(f.Current(), props);
    facesArea += props.Mass();
  }
  GProp_GProps area, volume;
  BRepGProp::SurfaceProperties(gear.solids[0], area);
  BRepGProp::VolumeProperties(gear.solids[0], volume);
  EXPECT_NEAR(area.Mass(), facesArea, 1e-6 * facesArea);
  EXPECT_GT(volume.Mass(), 0);
  EXPECT_NE(test::warningContaining(gear.warnings, "sewn at tolerance"), "");
}

// A small box with filleted edges, hollowed to 0.6 through its top face with
// OCCT's thick-solid offset (as FreeCAD's Part thickness does): the result
// has a misoriented sub-shape that BRepCheck rejects.
TopoDS_Shape hollowedFilletedBox() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(12, 8, 10).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(1.5, TopoDS::Edge(e.Current()));
  const TopoDS_Shape rounded = fillet.Shape();
  TopTools_ListOfShape open;
  for (TopExp_Explorer f(rounded, TopAbs_FACE); f.More(); f.Next()) {
    Bnd_Box b;
    BRepBndLib::Add(f.Current(), b);
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    if (z0 > 10 - 1e-6) open.Append(f.Current());  // the flat top
  }
  BRepOffsetAPI_MakeThickSolid thick;
  thick.MakeThickSolidByJoin(rounded, open, -0.6, 1e-4);
  return thick.Shape();
}

// An output folder that cannot be made (a file in the way of -o, or of its
// solid_<i> folder) is the documented exit 5 with one line, for `sample` and
// `run` alike (it was 1, from an uncaught filesystem error, before
// 2026-12-02), and nothing is computed or written after it.
TEST_F(BadInputs, UnwritableOutputFolderIsExitCodeFive) {
  const std::string box = std::string(CADMEDIAL_MODELS_DIR) + "/box.step";
  const std::string blocker = write("a_file", "in the way\n");
  fs::create_directories(dir_ / "has_solid_file");
  const std::string solidAsFile = write("has_solid_file/solid_0", "in the way\n");
  for (const std::string command : {"sample", "run"})
    for (const std::string& out : {blocker, blocker + "/sub", (dir_ / "has_solid_file").string()}) {
      std::string err;
      EXPECT_EQ(runCommand(command, box, "", out, err), kExitOutputFailed) << command << " -o " << out << "\n" << err;
      EXPECT_NE(err.find("cannot create the output folder"), std::string::npos) << err;
      EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    }
  std::ifstream still(solidAsFile);
  const std::string kept((std::istreambuf_iterator<char>(still)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "in the way\n");
  EXPECT_FALSE(fs::exists(dir_ / "has_solid_file" / "summary.json"));
}

// A spacing that would need more samples than any machine holds is refused
// at once, as a bad command line (exit 2, one line with a spacing that
// works), for `sample` and `run` alike, and nothing is written: `--spacing
// 1e-9` on a 60 mm box ran for 10 minutes without end before 2026-12-04.
// The library says the same with an InputError.
TEST_F(BadInputs, SpacingBeyondAnyMachineIsRefusedAtOnce) {
  const std::string box = std::string(CADMEDIAL_MODELS_DIR) + "/box.step";
  for (const std::string command : {"sample", "run"}) {
    const fs::path out = dir_ / ("tiny_spacing_" + command);
    std::string err;
    EXPECT_EQ(runCommand(command, box, "--spacing 1e-9", out.string(), err), kExitUsage) << command << "\n" << err;
    EXPECT_NE(err.find("spacing 1e-09 would need about"), std::string::npos) << err;
    EXPECT_NE(err.find("gives about a million"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(fs::exists(out / "solid_0")) << command;
  }
  SamplingParams params;
  params.spacing = 1e-9;
  try {
    sampleSolid(loadModel(box).solids.at(0), params);
    ADD_FAILURE() << "sampleSolid accepted a spacing of 1e-9";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), kExitUsage);
  }
  params.spacing = 1.0;  // 4,000 samples or so: accepted
  EXPECT_GT(sampleSolid(loadModel(box).solids.at(0), params).samples.size(), 1000u);
}

TEST_F(BadInputs, InvalidSolidIsRepairedAndSampled) {
  const TopoDS_Shape hollow = hollowedFilletedBox();
  // Without this precondition the test would not exercise the repair.
  if (BRepCheck_Analyzer(hollow).IsValid()) GTEST_SKIP() << "this OCCT builds a valid hollow box; nothing to repair";
  const std::string path = (dir_ / "hollow_box.brep").string();
  ASSERT_TRUE(BRepTools::Write(hollow, path.c_str()));

  const LoadedModel model = loadModel(path);
  ASSERT_EQ(model.solids.size(), 1u);
  EXPECT_TRUE(BRepCheck_Analyzer(model.solids[0]).IsValid());
  EXPECT_NE(test::warningContaining(model.warnings, "repaired with ShapeFix"), "");

  // The unrepaired solid sent the corner classification into an endless
  // loop inside OCCT; the CLI must now finish (time-boxed so a regression
  // fails instead of hanging the suite).
  const fs::path out = dir_ / "hollow_out";
  const std::string cmd = "timeout 120 " + std::string(CADMEDIAL_CLI) + " sample '" + path + "' -o '" +
                          out.string() + "' >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_TRUE(fs::exists(out / "solid_0" / "sampling.json"));
}

TEST_F(BadInputs, AssembliesAndMultiSolidFilesSampleEverySolid) {
  const std::string dir = test::publicModelsDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/models/public not present";
  const struct {
    const char* file;
    std::size_t solids;
  } cases[] = {{"as1_pe_203.stp", 18}, {"red_cube_blue_cylinder.step", 2}, {"nist_ctc_05_asme1_rd.stp", 1}};
  for (const auto& c : cases) {
    const LoadedModel model = loadModel(dir + "/" + c.file);
    EXPECT_EQ(model.solids.size(), c.solids) << c.file;
    for (const auto& solid : model.solids) {
      const SolidSampling r = sampleSolid(solid);
      EXPECT_GT(r.samples.size(), 0u) << c.file;
      EXPECT_TRUE(r.report.surface.closedManifold()) << c.file;
    }
  }
}

}  // namespace
}  // namespace cadmedial
