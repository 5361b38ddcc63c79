// writeRecords formats blocks of records in parallel: the text must still be
// every record once, in order, across block boundaries.
#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <string>

#include "medial_writers.hpp"
#include "number_text.hpp"
#include "record_writer.hpp"

namespace cadmedial {
namespace {

void appendRecord(std::size_t i, std::string& out) {
  appendInteger(out, i);
  out += ' ';
  appendNumber(out, 0.1 * static_cast<double>(i));
  if (i % 7 == 0) out += " seventh";  // records of different lengths
  out += '\n';
}

TEST(RecordWriter, SameTextAsOneThreadInOrder) {
  for (const std::size_t count : {0u, 1u, 8191u, 8192u, 8193u, 5u * 8192u + 17u}) {
    std::string expected = "header\n";
    for (std::size_t i = 0; i < count; ++i) appendRecord(i, expected);
    std::ostringstream stream;
    stream << "header\n";
    writeRecords(stream, count, appendRecord);
    SCOPED_TRACE(count);
    EXPECT_EQ(stream.str(), expected);
  }
}

TEST(RecordWriter, SeveralStreamsEachGetTheirTextInOrder) {
  for (const std::size_t count : {0u, 1u, 8192u, 3u * 8192u + 5u}) {
    std::string first, second;
    for (std::size_t i = 0; i < count; ++i) {
      appendRecord(i, first);
      appendRecord(2 * i + 1, second);
    }
    std::ostringstream a, b;
    writeRecordsTo<2>({&a, &b}, count, [](std::size_t i, std::array<std::string, 2>& texts) {
      appendRecord(i, texts[0]);
      appendRecord(2 * i + 1, texts[1]);
    });
    SCOPED_TRACE(count);
    EXPECT_EQ(a.str(), first);
    EXPECT_EQ(b.str(), second);
  }
}

// The CLI writes medial.obj and medial.ma together (their vertex lines share
// the formatted numbers): the same text as each written alone.
TEST(RecordWriter, ObjAndMaWrittenTogetherEqualEachWrittenAlone) {
  MedialComplex c;
  const std::size_t strips = 7000;  // 14 k vertices: more than one block
  for (std::size_t i = 0; i <= strips; ++i) {
    const double x = 0.1 * static_cast<double>(i) + 1e-9 / 3;
    c.vertices.push_back({x, 0, -x / 7});
    c.vertices.push_back({x, 1.0 / 3, 2e10 * x});
    c.radius.push_back(x / 3);
    c.radius.push_back(0);
  }
  for (std::size_t i = 0; i < strips; ++i) {  // quads and triangles, three sheets
    const Index a = static_cast<Index>(2 * i);
    if (i % 2 == 0) {
      for (Index v : {a, a + 2, a + 3, a + 1}) c.polygonVertices.push_back(v);
    } else {
      for (Index v : {a, a + 2, a + 3}) c.polygonVertices.push_back(v);
    }
    c.polygonOffsets.push_back(static_cast<Index>(c.polygonVertices.size()));
    c.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    c.sheet.push_back(static_cast<Index>(i % 3));
  }
  c.sheetCount = 3;
  std::ostringstream objAlone, maAlone, obj, ma;
  writeMedialObj(objAlone, c);
  writeMedialMa(maAlone, c);
  writeMedialObjAndMa(obj, ma, c);
  EXPECT_EQ(obj.str(), objAlone.str());
  EXPECT_EQ(ma.str(), maAlone.str());
  // Vertex 20's lines, numbers in the shortest form that reads back exactly.
  auto text = [](double v) {
    std::string out;
    appendNumber(out, v);
    return out;
  };
  const double x = 0.1 * 10 + 1e-9 / 3;
  const std::string numbers = text(x) + " 0 " + text(-x / 7);
  EXPECT_NE(obj.str().find("\nv " + numbers + " # r " + text(x / 3) + "\n"), std::string::npos);
  EXPECT_NE(ma.str().find("\nv " + numbers + " " + text(x / 3) + "\n"), std::string::npos);
  // 14 002 vertices; per strip a bottom edge, a rung and a diagonal, a top
  // edge on every other one, and the first rung: 3.5 x 7000 + 1 edges;
  // 3500 quads of two triangles and 3500 triangles.
  EXPECT_EQ(ma.str().substr(0, ma.str().find('\n')), "14002 24501 10500");
}

}  // namespace
}  // namespace cadmedial
