// Points that ask for a finer spacing around them (points along a face's
// fine convex edges, FaceSpacingField::gradeFrom), graded outward: the
// spacing they allow at p is  min over sources of  s + grading × |p - source|.
// A face's spacing field holds that on a 17 × 17 node grid, which on a big
// face is too coarse to see a small hole's rim (cells 31 mm wide on a 500 mm
// plate, where the rim needs ~1 mm within a few mm of it); this answers it at
// any point, with a k-d tree whose nodes know their finest source.
#pragma once

#include <memory>
#include <vector>

#include <gp_Pnt.hxx>

namespace cadmedial {

class SpacingSources {
 public:
  struct Source {
    gp_Pnt point;
    double spacing;
  };

  SpacingSources(std::vector<Source> sources, double grading);
  ~SpacingSources();
  SpacingSources(const SpacingSources&) = delete;  // held by pointer (FaceSpacingField)
  SpacingSources& operator=(const SpacingSources&) = delete;

  double finest() const { return finest_; }  // smallest source spacing (+inf if none)

  // min(upTo, min over sources of s + grading × max(0, |p - source| - slack)):
  // the spacing the sources allow anywhere within `slack` of p. Sources that
  // cannot go below `upTo` are not visited, so far from every source this
  // costs one step of the search.
  double allowedNear(const gp_Pnt& p, double slack, double upTo) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  double grading_;
  double finest_;
};

}  // namespace cadmedial
