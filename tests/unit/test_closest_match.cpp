// The "did you mean" search (io::closest_match): the banded edit distance gives the same
// suggestions as the full Levenshtein table for names up to kMaxSuggestedLength, and its
// work is bounded for long names (issue 22: two 100,000-character names took 53 s).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <random>
#include <string>
#include <vector>

#include "seaflex/io/yaml_reader.hpp"

namespace {

using seaflex::io::closest_match;
using seaflex::io::kMaxSuggestedLength;

// the full O(|a| |b|) table: the search as it was before the band
std::size_t full_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string reference_match(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    const std::size_t d = full_distance(name, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  const std::size_t limit = std::max<std::size_t>(1, std::max(name.size(), best.size()) / 3);
  return best_d <= limit ? best : std::string();
}

std::string random_name(std::mt19937& rng, std::size_t max_length) {
  // a small alphabet makes close candidates (and ties) frequent
  static const std::string kAlphabet = "abcAB_";
  std::uniform_int_distribution<std::size_t> length(0, max_length);
  std::uniform_int_distribution<std::size_t> letter(0, kAlphabet.size() - 1);
  std::string s(length(rng), 'a');
  for (auto& ch : s) ch = kAlphabet[letter(rng)];
  return s;
}

TEST(ClosestMatch, SameSuggestionsAsTheFullTableForNormalNames) {
  std::mt19937 rng(22);
  int suggested = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::size_t max_length = trial % 3 == 0 ? 40 : 8;
    std::vector<std::string> candidates;
    const int count = 1 + trial % 7;
    for (int c = 0; c < count; ++c) candidates.push_back(random_name(rng, max_length));
    // half of the names are a candidate with one or two letters changed
    std::string name = random_name(rng, max_length);
    if (trial % 2 == 0 && !candidates.front().empty()) {
      name = candidates[trial % candidates.size()];
      if (!name.empty()) name[trial % name.size()] = 'z';
      if (trial % 4 == 0) name += "Q";
    }
    const std::string expected = reference_match(name, candidates);
    ASSERT_EQ(closest_match(name, candidates), expected)
        << "name '" << name << "', trial " << trial;
    suggested += expected.empty() ? 0 : 1;
  }
  // the comparison covers both outcomes
  EXPECT_GT(suggested, 500);
  EXPECT_LT(suggested, 2900);
}

TEST(ClosestMatch, KnownSuggestions) {
  const std::vector<std::string> keys = {"outer_diameter", "inner_diameter", "youngs_modulus"};
  EXPECT_EQ(closest_match("outer_diametr", keys), "outer_diameter");
  EXPECT_EQ(closest_match("Youngs_Modulus", keys), "youngs_modulus");
  EXPECT_EQ(closest_match("density", keys), "");
  // equally close: the first candidate wins
  EXPECT_EQ(closest_match("ab", {"ax", "ay"}), "ax");
}

TEST(ClosestMatch, LongNamesCostBoundedWork) {
  // two 100,000-character names one letter apart: no suggestion and no table at all
  const std::string body(100000, 'r');
  std::string misspelt = body;
  misspelt[50000] = 's';
  std::size_t work = 1;
  EXPECT_EQ(closest_match(misspelt, {body, "riser"}, &work), "");
  EXPECT_EQ(work, 0u);

  // the longest name that is still searched: a 256-letter name one letter off its body
  const std::string longest(kMaxSuggestedLength, 'r');
  std::string near = longest;
  near[100] = 's';
  EXPECT_EQ(closest_match(near, {longest}, &work), longest);
  // the band is 2 * (256 / 3) + 1 = 171 cells wide: at most 256 x 171 cells (the full
  // table would be 256 x 256 = 65,536)
  EXPECT_LE(work, kMaxSuggestedLength * 171);
  // a candidate over the limit is not suggested, even when it is the only close one
  EXPECT_EQ(closest_match(std::string(kMaxSuggestedLength + 1, 'r'),
                          {std::string(kMaxSuggestedLength + 2, 'r')}),
            "");
}

TEST(ClosestMatch, DistantCandidatesStopEarly) {
  // 1,000 candidates of 200 letters, none close: each stops after about the band's width
  // in rows, not after 200 rows
  std::vector<std::string> candidates(1000, std::string(200, 'x'));
  std::size_t work = 0;
  EXPECT_EQ(closest_match(std::string(200, 'y'), candidates, &work), "");
  // the band is 2 * 66 + 1 = 133 cells; every cell of row i is at least i - 66 + ... the
  // row minimum passes 66 after 67 rows: at most 67 rows x 133 cells a candidate
  EXPECT_LE(work, 1000u * 67u * 133u);
}

}  // namespace
