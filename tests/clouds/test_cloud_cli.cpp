// `cadmedial run` on point clouds and meshes: every format, the inner axis of a
// closed mesh checked against the exact torus, whole axis for clouds and open
// meshes, one-line errors with exit code 3 and no output for bad files.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "analytic_shapes.hpp"
#include "cadmedial/errors.hpp"
#include "medial_ply_io.hpp"

namespace cadmedial {
namespace {

namespace fs = std::filesystem;

// A closed torus mesh (R = 2, r = 0.7): jittered parameter grid, outward
// oriented triangles. Vertices lie exactly on the torus.
struct TorusMesh {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;
};
TorusMesh torusMesh(int nu = 120, int nv = 40) {
  TorusMesh m;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(0, 0.3);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * (i + jitter(rng)) / nu, w = 2 * M_PI * (j + jitter(rng)) / nv;
      m.v.push_back({(2 + 0.7 * std::cos(w)) * std::cos(u), (2 + 0.7 * std::cos(w)) * std::sin(u), 0.7 * std::sin(w)});
    }
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

class CloudCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cadmedial_clouds_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string writeMesh(const std::string& name, const TorusMesh& m, std::size_t dropFaces = 0) {
    char buf[128];
    std::string s;
    const std::string ext = fs::path(name).extension().string();
    if (ext == ".off") {
      s = "OFF\n" + std::to_string(m.v.size()) + " " + std::to_string(m.f.size() - dropFaces) + " 0\n";
      for (const Vec3& p : m.v) s += (std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]), buf);
      for (std::size_t k = dropFaces; k < m.f.size(); ++k)
        s += (std::snprintf(buf, sizeof buf, "3 %d %d %d\n", m.f[k][0], m.f[k][1], m.f[k][2]), buf);
    } else if (ext == ".obj") {
      for (const Vec3& p : m.v) s += (std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]), buf);
      for (const auto& t : m.f) s += (std::snprintf(buf, sizeof buf, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1), buf);
    } else if (ext == ".ply") {
      s = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(m.v.size()) +
          "\nproperty double x\nproperty double y\nproperty double z\n" +
          (m.f.empty() ? "" : "element face " + std::to_string(m.f.size()) + "\nproperty list uchar int vertex_indices\n") +
          "end_header\n";
      for (const Vec3& p : m.v) s += (std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]), buf);
      for (const auto& t : m.f) s += (std::snprintf(buf, sizeof buf, "3 %d %d %d\n", t[0], t[1], t[2]), buf);
    } else if (ext == ".stl") {  // binary
      s.assign(80, '\0');
      const std::uint32_t n = static_cast<std::uint32_t>(m.f.size());
      s.append(reinterpret_cast<const char*>(&n), 4);
      for (const auto& t : m.f) {
        float rec[12] = {0, 0, 0};
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 3; ++k) rec[3 + 3 * c + k] = static_cast<float>(m.v[t[c]][k]);
        s.append(reinterpret_cast<const char*>(rec), sizeof rec);
        s.append(2, '\0');
      }
    }
    return write(name, s);
  }

  // Runs `cadmedial run`; returns the exit code, stderr in err.
  int run(const std::string& input, std::string& err, const std::string& extra = "") {
    const fs::path errFile = dir_ / "stderr.txt";
    fs::remove_all(dir_ / "out");
    const std::string cmd = std::string(CADMEDIAL_CLI) + " run '" + input + "' -o '" + (dir_ / "out").string() + "' " +
                            extra + " >/dev/null 2>'" + errFile.string() + "'";
    const int status = std::system(cmd.c_str());
    std::ifstream in(errFile);
    err.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  nlohmann::json summary() const {
    std::ifstream in(dir_ / "out" / "solid_0" / "summary.json");
    return nlohmann::json::parse(in);
  }
  MedialMesh medial() const {
    std::ifstream in(dir_ / "out" / "solid_0" / "medial.ply");
    return readMedialPly(in, "medial.ply");
  }
  static MedialComplex complexOf(const MedialMesh& m) {
    MedialComplex c;
    c.vertices = m.vertices;
    c.radius = m.radius;
    c.polygonOffsets.assign(m.polygonOffsets.begin(), m.polygonOffsets.end());
    c.polygonVertices.assign(m.polygonVertices.begin(), m.polygonVertices.end());
    return c;
  }
  fs::path dir_;
};

TEST_F(CloudCli, ClosedMeshesGiveTheInnerAxisInEveryFormat) {
  const TorusMesh mesh = torusMesh();
  const auto torus = testing::makeTorus(2.0, 0.7);
  for (const std::string name : {"torus.off", "torus.obj", "torus.ply", "torus.stl"}) {
    std::string err;
    ASSERT_EQ(run(writeMesh(name, mesh), err), kExitOk) << name << ": " << err;
    const nlohmann::json s = summary();
    EXPECT_EQ(s["algorithm"], "MEDIAL") << name;
    EXPECT_EQ(s["axis"], "inner") << name;
    EXPECT_EQ(s["input"]["points"], mesh.v.size()) << name;
    EXPECT_DOUBLE_EQ(s["parameters"]["theta_deg"].get<double>(), 22.5) << name;  // π/8 unless --theta
    // The torus' inner axis is its core circle (β0 = β1 = 1).
    EXPECT_EQ(s["topology"]["beta0"], 1) << name;
    EXPECT_EQ(s["topology"]["beta1"], 1) << name;
    const testing::AnalyticMeasure m = testing::measureAgainstShape(complexOf(medial()), *torus, false);
    std::printf("%-10s inside %.4f axis p90 %.5f max %.5f |d-r| p90 %.5f coverage %.4f\n", name.c_str(),
                m.insideShare, m.axisP90, m.axisMax, m.medialP90, m.coverage);
    EXPECT_EQ(m.insideShare, 1.0) << name;
    EXPECT_LE(m.axisP90, 0.01) << name;  // 2 tol
    EXPECT_LE(m.medialMedian, 0.005) << name;
    EXPECT_LE(m.medialP90, 0.01) << name;
    EXPECT_GE(m.coverage, 0.99) << name;
  }
}

TEST_F(CloudCli, CloudsAndOpenMeshesGiveTheWholeAxis) {
  TorusMesh cloud = torusMesh();
  const auto torus = testing::makeTorus(2.0, 0.7);
  std::string err;
  // .ply without faces, .xyz, .pts with a count line and extra columns.
  std::string xyz, pts = std::to_string(cloud.v.size()) + "\n";
  char buf[160];
  for (const Vec3& p : cloud.v) {
    xyz += (std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p[0], p[1], p[2]), buf);
    pts += (std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g 17 200 10 10\n", p[0], p[1], p[2]), buf);
  }
  const TorusMesh closed = cloud;
  cloud.f.clear();
  for (const std::string& input : {writeMesh("cloud.ply", cloud), write("cloud.xyz", "# torus\n" + xyz),
                                   write("cloud.PTS", pts), writeMesh("open.off", closed, 40)}) {
    ASSERT_EQ(run(input, err), kExitOk) << input << ": " << err;
    const nlohmann::json s = summary();
    EXPECT_EQ(s["axis"], "whole") << input;
    EXPECT_NE(s["axis_note"].get<std::string>().find("whole medial axis"), std::string::npos) << input;
    // Whole axis = core circle ∪ z axis (outer): measured against both.
    const testing::AnalyticMeasure m = testing::measureAgainstShape(complexOf(medial()), *torus, true);
    EXPECT_LT(m.insideShare, 0.95) << input;  // the outer axis is there too
    EXPECT_LE(m.axisP90, 0.01) << input;
    EXPECT_GE(m.coverage, 0.99) << input;
  }
  // --theta overrides the point-cloud default.
  ASSERT_EQ(run((dir_ / "cloud.xyz").string(), err, "--theta 10"), kExitOk) << err;
  EXPECT_DOUBLE_EQ(summary()["parameters"]["theta_deg"].get<double>(), 10.0);
}

TEST_F(CloudCli, BadFilesAreOneLineErrorsWithCode3AndNoOutput) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"missing.xyz", ""},  // not written
      {"empty.stl", ""},
      {"letters.xyz", "1 2 3\n4 5 x\n1 1 1\n2 2 2\n"},
      {"short.xyz", "1 2 3\n4 5\n"},
      {"few.pts", "2\n1 2 3\n4 5 6\n"},
      {"nan.xyz", "1 2 3\n4 5 6\n1 1 1\n0 0 nan\n"},
      {"garbage.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n"},
      {"garbage.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nend_header\n1\n"},
      {"garbage.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n"},
      {"badindex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 9\n"},
      {"binary.obj", std::string("\x7f\x45\x4c\x46\x02\x01\x01\0\0\0", 10)},
  };
  for (const auto& [name, text] : bad) {
    const std::string path = name == "missing.xyz" ? (dir_ / name).string() : write(name, text);
    std::string err;
    EXPECT_EQ(run(path, err), kExitUnreadableInput) << name << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << name << ": " << err;
    EXPECT_EQ(err.rfind("error: ", 0), 0u) << name << ": " << err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "solid_0" / "summary.json")) << name;
  }
  // An unknown extension: the message lists the point formats too.
  std::string err;
  EXPECT_EQ(run(write("notes.md", "hello\n"), err), kExitUnreadableInput);
  EXPECT_NE(err.find(".xyz .pts .ply .stl .obj .off"), std::string::npos) << err;
}

}  // namespace
}  // namespace cadmedial
