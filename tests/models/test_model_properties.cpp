// Checks the committed STEP models in models/ against the hand-derived
// reference in models/expected.json (see models/EXPECTED.md), and checks that
// cadmedial_generate_models still produces the same models.
//
// Only what needs no convexity classifier is verified here: topology counts,
// Euler characteristic vs. genus, total edge length, volume and area. The
// convex/concave/smooth and corner counts are the reference the project's
// classifier is tested against elsewhere; here we only check that they are
// consistent with the topology (they partition the edges, lengths add up).

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kModelsDir = CADMEDIAL_MODELS_DIR;

// ---------------------------------------------------------------------------
// Tiny evaluator for the closed-form formulas in expected.json:
// numbers, + - * / ^, parentheses, unary minus, `pi`, `sqrt(...)`.
class Formula {
 public:
  static double eval(const std::string& text) {
    Formula f(text);
    double v = f.sum();
    f.skipSpace();
    if (f.pos_ != f.s_.size()) throw std::runtime_error("trailing input in formula: " + text);
    return v;
  }

 private:
  explicit Formula(const std::string& s) : s_(s) {}
  void skipSpace() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skipSpace();
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  void expect(char c) {
    if (!accept(c)) throw std::runtime_error(std::string("expected '") + c + "' in formula: " + s_);
  }
  double sum() {
    double v = product();
    for (;;) {
      if (accept('+')) v += product();
      else if (accept('-')) v -= product();
      else return v;
    }
  }
  double product() {
    double v = power();
    for (;;) {
      if (accept('*')) v *= power();
      else if (accept('/')) v /= power();
      else return v;
    }
  }
  double power() {
    double base = unary();
    return accept('^') ? std::pow(base, power()) : base;  // right-associative
  }
  double unary() { return accept('-') ? -unary() : atom(); }
  double atom() {
    skipSpace();
    if (accept('(')) {
      double v = sum();
      expect(')');
      return v;
    }
    if (s_.compare(pos_, 2, "pi") == 0) return pos_ += 2, std::acos(-1.0);
    if (s_.compare(pos_, 4, "sqrt") == 0) {
      pos_ += 4;
      expect('(');
      double v = sum();
      expect(')');
      return std::sqrt(v);
    }
    std::size_t used = 0;
    double v = std::stod(s_.substr(pos_), &used);  // throws on garbage
    pos_ += used;
    return v;
  }
  std::string s_;
  std::size_t pos_ = 0;
};

// ---------------------------------------------------------------------------
// What we measure on a B-rep.
struct Measured {
  int solids = 0, shells = 0;
  bool closedShell = false, valid = false;
  int faces = 0, vertices = 0, innerWires = 0;
  int edges = 0;  // excluding seam and degenerated edges (the EXPECTED.md convention)
  int seamEdges = 0, degeneratedEdges = 0;
  double edgeLength = 0;  // total length of the counted edges
  double volume = 0, area = 0;
};

void silenceOcct() {
  static bool done = false;
  if (!done) Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  done = true;
}

TopoDS_Shape readStep(const fs::path& file) {
  silenceOcct();
  STEPControl_Reader reader;
  if (reader.ReadFile(file.string().c_str()) != IFSelect_RetDone)
    throw std::runtime_error("cannot read " + file.string());
  reader.TransferRoots();
  return reader.OneShape();
}

double relDiff(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

Measured measure(const TopoDS_Shape& shape) {
  Measured m;
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) ++m.solids;
  for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next()) {
    ++m.shells;
    m.closedShell = BRep_Tool::IsClosed(ex.Current());  // every edge bounds two face sides
  }
  m.valid = BRepCheck_Analyzer(shape).IsValid();

  TopTools_IndexedMapOfShape faces, vertices;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  m.faces = faces.Extent();
  m.vertices = vertices.Extent();
  for (int i = 1; i <= faces.Extent(); ++i) {
    int wires = 0;
    for (TopExp_Explorer ex(faces(i), TopAbs_WIRE); ex.More(); ex.Next()) ++wires;
    m.innerWires += wires - 1;
  }

  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edgeFaces.FindKey(i));
    if (BRep_Tool::Degenerated(e)) {
      ++m.degeneratedEdges;
      continue;
    }
    // A seam carries two p-curves on the one face it bounds twice.
    bool seam = false;
    for (const TopoDS_Shape& f : edgeFaces(i)) seam = seam || BRep_Tool::IsClosed(e, TopoDS::Face(f));
    if (seam) {
      ++m.seamEdges;
      continue;
    }
    ++m.edges;
    GProp_GProps lp;
    BRepGProp::LinearProperties(e, lp);
    m.edgeLength += lp.Mass();
  }

  GProp_GProps vp, sp;
  BRepGProp::VolumeProperties(shape, vp, 1e-10);
  BRepGProp::SurfaceProperties(shape, sp, 1e-10);
  m.volume = vp.Mass();
  m.area = sp.Mass();
  return m;
}

// ---------------------------------------------------------------------------
json loadExpected() {
  std::ifstream in(kModelsDir / "expected.json");
  if (!in) throw std::runtime_error("cannot open " + (kModelsDir / "expected.json").string());
  return json::parse(in);
}

// Model names for the parameterized tests (empty if expected.json is broken;
// ExpectedJson.Loads then reports why).
std::vector<std::string> modelNames() {
  std::vector<std::string> names;
  try {
    const json doc = loadExpected();
    for (const json& m : doc.at("models")) names.push_back(m.at("name").get<std::string>());
  } catch (const std::exception&) {
  }
  return names;
}

json expectedFor(const std::string& name) {
  const json doc = loadExpected();  // keep alive: range-for would not extend it
  for (const json& m : doc.at("models"))
    if (m.at("name") == name) return m;
  throw std::runtime_error("no model " + name + " in expected.json");
}

double formulaValue(const json& q) { return Formula::eval(q.at("formula").get<std::string>()); }

TEST(ExpectedJson, Loads) {
  json doc;
  ASSERT_NO_THROW(doc = loadExpected());
  ASSERT_TRUE(doc.contains("models"));
  EXPECT_FALSE(doc["models"].empty());
}

TEST(ExpectedJson, EveryStepFileIsListed) {
  std::set<std::string> listed, onDisk;
  const json doc = loadExpected();
  for (const json& m : doc.at("models")) listed.insert(m.at("file").get<std::string>());
  for (const auto& entry : fs::directory_iterator(kModelsDir))
    if (entry.path().extension() == ".step") onDisk.insert(entry.path().filename().string());
  EXPECT_EQ(listed, onDisk);
}

TEST(Formula, Evaluates) {
  EXPECT_DOUBLE_EQ(Formula::eval("2*(3+4) - 10/4"), 11.5);
  EXPECT_DOUBLE_EQ(Formula::eval("2^3^2"), 512.0);
  EXPECT_DOUBLE_EQ(Formula::eval("-pi*sqrt(4)"), -2 * std::acos(-1.0));
  EXPECT_THROW(Formula::eval("2*(3"), std::runtime_error);
}

// ---------------------------------------------------------------------------
class ModelProperties : public ::testing::TestWithParam<std::string> {};

TEST_P(ModelProperties, MatchesHandDerivedReference) {
  const json x = expectedFor(GetParam());
  const Measured m = measure(readStep(kModelsDir / x.at("file").get<std::string>()));

  EXPECT_EQ(m.solids, 1);
  EXPECT_EQ(m.shells, 1);
  EXPECT_TRUE(m.closedShell);
  EXPECT_TRUE(m.valid);

  EXPECT_EQ(m.faces, x.at("faces").get<int>());
  EXPECT_EQ(m.edges, x.at("edges").get<int>());
  EXPECT_EQ(m.seamEdges, x.at("seam_edges").get<int>());
  EXPECT_EQ(m.degeneratedEdges, x.at("degenerated_edges").get<int>());
  EXPECT_EQ(m.vertices, x.at("vertices").get<int>());
  EXPECT_EQ(m.innerWires, x.at("inner_wires").get<int>());

  // Euler: with seams and degenerated edges counted, every face is a disc once
  // its inner wires are accounted for, so V - E_all + F - (inner wires) = 2 - 2g.
  const int allEdges = m.edges + m.seamEdges + m.degeneratedEdges;
  EXPECT_EQ(m.vertices - allEdges + m.faces - m.innerWires, 2 - 2 * x.at("genus").get<int>());

  // Every counted edge is exactly one of convex / concave / smooth, and the
  // per-kind lengths add up to the measured total.
  EXPECT_EQ(x.at("convex_edges").get<int>() + x.at("concave_edges").get<int>() +
                x.at("smooth_edges").get<int>(),
            m.edges);
  const double kindLengths = formulaValue(x.at("convex_length")) +
                             formulaValue(x.at("concave_length")) +
                             formulaValue(x.at("smooth_length"));
  EXPECT_NEAR(kindLengths, m.edgeLength, 1e-6 * std::max(1.0, m.edgeLength));
  EXPECT_LE(x.at("nonconcave_corners").get<int>(), x.at("corners").get<int>());
  EXPECT_LE(x.at("corners").get<int>(), m.vertices);

  // Stored values match their formulas; OCCT's integration matches both.
  for (const char* key : {"volume", "area", "convex_length", "concave_length", "smooth_length"}) {
    const double f = formulaValue(x.at(key));
    EXPECT_NEAR(f, x.at(key).at("value").get<double>(), 1e-9 * std::max(1.0, std::abs(f))) << key;
  }
  EXPECT_LT(relDiff(m.volume, formulaValue(x.at("volume"))), 1e-6)
      << "volume " << m.volume << " vs " << x["volume"]["formula"];
  EXPECT_LT(relDiff(m.area, formulaValue(x.at("area"))), 1e-6)
      << "area " << m.area << " vs " << x["area"]["formula"];
}

// ---------------------------------------------------------------------------
// Regenerating into a temporary directory gives the same models as the
// committed files, so the generator and the files cannot drift apart.
class Regeneration : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    dir_ = fs::temp_directory_path() / ("cadmedial_models_" + std::to_string(stamp));
    const std::string cmd =
        std::string("\"") + CADMEDIAL_GENERATOR + "\" \"" + dir_.string() + "\" > /dev/null";
    status_ = std::system(cmd.c_str());
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  static inline fs::path dir_;
  static inline int status_ = -1;
};

TEST_P(Regeneration, SameModelAsCommittedFile) {
  ASSERT_EQ(status_, 0) << "generator failed: " << CADMEDIAL_GENERATOR;
  const std::string file = expectedFor(GetParam()).at("file");
  ASSERT_TRUE(fs::exists(dir_ / file)) << "generator did not write " << file;
  const Measured committed = measure(readStep(kModelsDir / file));
  const Measured fresh = measure(readStep(dir_ / file));
  EXPECT_EQ(fresh.solids, committed.solids);
  EXPECT_EQ(fresh.faces, committed.faces);
  EXPECT_EQ(fresh.edges, committed.edges);
  EXPECT_EQ(fresh.seamEdges, committed.seamEdges);
  EXPECT_EQ(fresh.vertices, committed.vertices);
  EXPECT_EQ(fresh.innerWires, committed.innerWires);
  EXPECT_LT(relDiff(fresh.volume, committed.volume), 1e-9);
  EXPECT_LT(relDiff(fresh.area, committed.area), 1e-9);
  EXPECT_LT(relDiff(fresh.edgeLength, committed.edgeLength), 1e-9);
}

std::string paramName(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

INSTANTIATE_TEST_SUITE_P(Models, ModelProperties, ::testing::ValuesIn(modelNames()), paramName);
INSTANTIATE_TEST_SUITE_P(Models, Regeneration, ::testing::ValuesIn(modelNames()), paramName);

}  // namespace
