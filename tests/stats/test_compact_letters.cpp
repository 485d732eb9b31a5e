// Compact letter display (Piepho 2004): hand-worked cases, and on every decision pattern of up
// to 5 lines the defining property (two lines share a letter exactly when they were not found
// different) and the sweep's minimality (no line can lose a letter without breaking it).
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/stats/compact_letters.hpp"
#include "support/shared_letter.hpp"

using namespace growthuq;
using growthuq::testing::share_letter;

namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

bool differ(const Pairs& pairs, std::size_t i, std::size_t j) {
  for (const auto& [a, b] : pairs) {
    if ((a == i && b == j) || (a == j && b == i)) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("compact letters: hand-worked cases") {
  // No pair differs: one letter for all.
  CHECK(compact_letters(3, Pairs{}) == std::vector<std::string>{"a", "a", "a"});
  // Every pair differs: a letter each.
  CHECK(compact_letters(3, Pairs{{0, 1}, {0, 2}, {1, 2}}) == std::vector<std::string>{"a", "b", "c"});
  // Not transitive: A ~ B, B ~ C, A != C. {ABC} splits into {BC} and {AB}; ordered by first line,
  // {AB} is a, {BC} is b.
  CHECK(compact_letters(3, Pairs{{0, 2}}) == std::vector<std::string>{"a", "ab", "b"});
  CHECK(compact_letters(3, Pairs{{2, 0}}) == std::vector<std::string>{"a", "ab", "b"});
  // One pair of four differs (A != B): {ABCD} -> {BCD}, {ACD}; a = {ACD}, b = {BCD}.
  CHECK(compact_letters(4, Pairs{{0, 1}}) == std::vector<std::string>{"a", "b", "ab", "ab"});
  // A chain: A != C, A != D, B != D. {ABCD} -> {BCD}, {ABD}; (A,D): {ABD} -> {BD} (absorbed by
  // {BCD}), {AB}; (B,D): {BCD} -> {CD}, {BC}. Letters {AB} a, {BC} b, {CD} c.
  CHECK(compact_letters(4, Pairs{{0, 2}, {0, 3}, {1, 3}}) == std::vector<std::string>{"a", "ab", "bc", "c"});
  // The last line apart from the others, which agree: a a a b.
  CHECK(compact_letters(4, Pairs{{0, 3}, {1, 3}, {2, 3}}) == std::vector<std::string>{"a", "a", "a", "b"});
  // One line, none.
  CHECK(compact_letters(1, Pairs{}) == std::vector<std::string>{"a"});
  CHECK(compact_letters(0, Pairs{}).empty());
}

TEST_CASE("compact letters: more than 26 letters go on with capitals") {
  // 30 lines all different: a..z, then A..D.
  Pairs all;
  for (std::size_t i = 0; i < 30; ++i) {
    for (std::size_t j = i + 1; j < 30; ++j) all.emplace_back(i, j);
  }
  const std::vector<std::string> letters = compact_letters(30, all);
  CHECK(letters[0] == "a");
  CHECK(letters[25] == "z");
  CHECK(letters[26] == "A");
  CHECK(letters[29] == "D");
}

TEST_CASE("compact letters: on every decision pattern of 2 to 5 lines, lines share a letter exactly when not different, and no letter is redundant") {
  std::size_t patterns = 0;
  for (std::size_t lines = 2; lines <= 5; ++lines) {
    Pairs every;
    for (std::size_t i = 0; i < lines; ++i) {
      for (std::size_t j = i + 1; j < lines; ++j) every.emplace_back(i, j);
    }
    for (std::size_t mask = 0; mask < (std::size_t{1} << every.size()); ++mask) {
      Pairs differing;
      for (std::size_t p = 0; p < every.size(); ++p) {
        if (mask & (std::size_t{1} << p)) differing.push_back(every[p]);
      }
      const std::vector<std::string> letters = compact_letters(lines, differing);
      CAPTURE(lines);
      CAPTURE(mask);
      REQUIRE(letters.size() == lines);
      for (std::size_t i = 0; i < lines; ++i) {
        REQUIRE(!letters[i].empty());
        for (std::size_t j = i + 1; j < lines; ++j) REQUIRE(share_letter(letters[i], letters[j]) == !differ(differing, i, j));
      }
      // Minimal: without any one of a line's letters (when it has several) some pair it did not
      // differ from would no longer share a letter.
      for (std::size_t i = 0; i < lines; ++i) {
        if (letters[i].size() < 2) continue;
        for (std::size_t l = 0; l < letters[i].size(); ++l) {
          std::vector<std::string> fewer = letters;
          fewer[i].erase(l, 1);
          bool broken = false;
          for (std::size_t j = 0; j < lines; ++j) {
            if (j != i && !differ(differing, i, j) && !share_letter(fewer[i], fewer[j])) broken = true;
          }
          CAPTURE(i);
          CAPTURE(letters[i]);
          CHECK(broken);
        }
      }
      ++patterns;
    }
  }
  CHECK(patterns == 2 + 8 + 64 + 1024);
}

TEST_CASE("compact letters: an index out of range or a line paired with itself is a programming error") {
  CHECK_THROWS_AS(compact_letters(3, Pairs{{0, 3}}), std::invalid_argument);
  CHECK_THROWS_AS(compact_letters(3, Pairs{{1, 1}}), std::invalid_argument);
}
