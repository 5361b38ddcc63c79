// medial.ply: exact round trip, polygons above the uchar corner limit, and a
// clear error for every kind of malformed file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "box_axis.hpp"
#include "cadmedial/errors.hpp"
#include "medial_ply_io.hpp"

namespace cadmedial {
namespace {

const char* kHeader =
    "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 3\nproperty double x\nproperty double y\n"
    "property double z\nproperty double radius\nelement face 1\nproperty list uchar int vertex_indices\n"
    "property int sheet\nproperty uchar provenance\nend_header\n";
const char* kBody = "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n3 0 1 2 7 1\n";

MedialMesh parse(const std::string& text) {
  std::istringstream in(text);
  return readMedialPly(in, "medial.ply");
}

void expectSameMesh(const MedialMesh& a, const MedialMesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.polygonOffsets, b.polygonOffsets);
  EXPECT_EQ(a.polygonVertices, b.polygonVertices);
  EXPECT_EQ(a.sheet, b.sheet);
  EXPECT_EQ(a.provenance, b.provenance);
}

TEST(MedialPly, HandWrittenFileReads) {
  const MedialMesh m = parse(std::string(kHeader) + kBody);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.radius[1], 0.5);
  ASSERT_EQ(m.polygonCount(), 1u);
  EXPECT_EQ(m.sheet[0], 7);
  EXPECT_EQ(m.provenance[0], MedialProvenance::ConvexEdgeTriangle);
}

TEST(MedialPly, RoundTripIsExact) {
  MedialMesh mesh = test::exactBoxAxis(5);
  mesh.vertices[0] = {0.1, 1.0 / 3, -2.5e-300};  // numbers that need all 17 digits
  mesh.radius[0] = 2.0 / 3;
  mesh.provenance[3] = MedialProvenance::CornerTriangle;
  mesh.addPolygon({0, 1, 2, 3}, 99, MedialProvenance::ConvexEdgeFill);
  std::stringstream buffer;
  writeMedialPly(buffer, mesh);
  expectSameMesh(readMedialPly(buffer, "buffer"), mesh);

  const std::string dir = ::testing::TempDir() + "/medial_ply_round_trip";
  std::filesystem::create_directories(dir);
  writeMedialPlyFile(dir + "/medial.ply", mesh);
  expectSameMesh(readMedialPlyFile(dir + "/medial.ply"), mesh);
  for (const auto& entry : std::filesystem::directory_iterator(dir))  // no temporary left behind
    EXPECT_EQ(entry.path().filename(), "medial.ply");
}

TEST(MedialPly, PolygonsAboveTheUcharLimitAreSplitIntoAFan) {
  MedialMesh mesh;
  std::vector<std::uint32_t> ring;
  for (std::uint32_t i = 0; i < 600; ++i) {
    const double a = 2 * 3.14159265358979 * i / 600;
    ring.push_back(mesh.addVertex({std::cos(a), std::sin(a), 0}, 1));
  }
  mesh.addPolygon(ring, 4, MedialProvenance::VoronoiFacet);
  std::stringstream buffer;
  writeMedialPly(buffer, mesh);
  const MedialMesh back = readMedialPly(buffer, "buffer");
  ASSERT_EQ(back.polygonCount(), 3u);  // 255 + 255 + 92 corners, each sharing corner 0
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < back.polygonCount(); ++i) {
    EXPECT_LE(back.polygonOffsets[i + 1] - back.polygonOffsets[i], 255u);
    EXPECT_EQ(back.polygonVertices[back.polygonOffsets[i]], 0u);
    EXPECT_EQ(back.sheet[i], 4);
    triangles += back.polygonOffsets[i + 1] - back.polygonOffsets[i] - 2;
  }
  EXPECT_EQ(triangles, 598u);  // same fan triangles as the original polygon
  const TopologyMetric before = medialComplexTopology(mesh, 100), after = medialComplexTopology(back, 100);
  EXPECT_EQ(before.euler, after.euler);
  EXPECT_EQ(before.beta1, after.beta1);
}

// Every malformed file gives InputError(kExitUnreadableInput) naming the file
// and line, and saying what is wrong.
void expectRejected(const std::string& text, const std::string& lineAndWhat) {
  try {
    parse(text);
    ADD_FAILURE() << "accepted: " << lineAndWhat;
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), kExitUnreadableInput);
    EXPECT_NE(std::string(e.what()).find("medial.ply: line " + lineAndWhat), std::string::npos) << e.what();
  }
}

TEST(MedialPly, MalformedFilesAreRejectedWithLineNumbers) {
  const std::string header(kHeader), body(kBody);
  expectRejected("", "1: file ends early");
  expectRejected("solid x\n", "1: not a PLY file");
  expectRejected("ply\nformat binary_little_endian 1.0\n", "2: expected 'format ascii 1.0'");
  expectRejected("ply\nformat ascii 1.0\nelement vertex -3\n", "3: bad element count");
  std::string swapped = header;
  swapped.replace(swapped.find("property double z\nproperty double radius"), 40, "property double radius\nproperty double z");
  expectRejected(swapped + body, "7: expected 'property double z'");
  std::string floatIndices = header;
  floatIndices.replace(floatIndices.find("uchar int"), 9, "uchar uint");
  expectRejected(floatIndices + body, "10: expected 'property list uchar int vertex_indices'");
  expectRejected(header + "0 0 0\n", "14: vertex 0: expected 4 numbers");
  expectRejected(header + "0 0 zero 0\n", "14: bad z 'zero'");
  expectRejected(header + "0 0 0 nan\n", "14: bad radius 'nan'");
  expectRejected(header + "0 0 0 -1\n", "14: vertex 0: negative radius");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n", "16: file ends early, expected a vertex line");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n3 0 1 3 7 1\n", "17: bad vertex index '3'");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n2 0 1 7 1\n", "17: bad corner count");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n3 0 1 2 7\n", "17: face 0: expected 6 values");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n3 0 1 2 7 5\n", "17: bad provenance");
  expectRejected(header + "0 0 0 0\n1 0 0 0.5\n0 1 0 0.25\n3 0 1 2 -1 0\n", "17: bad sheet");
  expectRejected(header + body + "1 2 3\n", "18: unexpected data after the last face");
  EXPECT_NO_THROW(parse(header + body + "\n\n"));  // trailing blank lines are fine
}

TEST(MedialPly, MissingFileIsAnInputError) {
  try {
    readMedialPlyFile(::testing::TempDir() + "/no/such/medial.ply");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), kExitUnreadableInput);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace cadmedial
