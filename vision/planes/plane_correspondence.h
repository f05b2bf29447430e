#pragma once
#include <array>
#include <bitset>

#include "vision/planes/plane_registration_config.h"
#include "vision/planes/plane_set.h"

namespace deepnav {

struct PlaneMatch {
  int a = -1;  // plane index in the set of image a
  int b = -1;  // plane index in the set of image b
};

// Correspondences between two plane sets with unknown correspondences (Pathak et al. T-RO 2010):
// the M x N candidate pairs are filtered by the unary tests (size similarity, rotation prior);
// two candidates are consistent when they use distinct planes and pass the cross-angle test
// (the angle between two planes is invariant to the motion) and, for parallel planes, the
// parallel-consistency test (their offset difference is invariant too). The largest set of
// mutually consistent candidates (a maximum clique, branch and bound on bitsets; ties broken by
// the planes' point counts) is the correspondence. A lone candidate passes on the size test
// alone. Fixed capacities: kMaxCandidates pairs, adjacency as bitsets.
class PlaneCorrespondenceSearch {
 public:
  static constexpr int kMaxCandidates = 256;
  static constexpr int kMaxMatches = 64;

  bool init(const PlaneRegistrationConfig& config);
  // Writes up to kMaxMatches matches; returns their number.
  int find(const PlaneSet& a, const PlaneSet& b, std::array<PlaneMatch, kMaxMatches>* matches);

  int candidateCount() const { return candidate_count_; }
  bool searchExhausted() const { return exhausted_; }

 private:
  using Bits = std::bitset<kMaxCandidates>;
  bool consistent(const PlaneSet& a, const PlaneSet& b, const PlaneMatch& u,
                  const PlaneMatch& v) const;
  void expand(Bits candidates, int depth, double score);

  PlaneRegistrationConfig config_;
  double cos_max_normal_change_ = -1.0;
  std::array<PlaneMatch, kMaxCandidates> candidates_{};
  std::array<double, kMaxCandidates> candidate_score_{};
  std::array<Bits, kMaxCandidates> adjacent_{};
  int candidate_count_ = 0;
  std::array<int, kMaxMatches> current_{};
  std::array<int, kMaxMatches> best_{};
  int best_size_ = 0;
  double best_score_ = 0.0;
  long nodes_ = 0;
  bool exhausted_ = false;
};

}  // namespace deepnav
