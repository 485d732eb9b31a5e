#include "growthuq/stats/compact_letters.hpp"

#include <algorithm>
#include <stdexcept>

namespace growthuq {
namespace {

// A letter: the set of lines that carry it, one flag per line.
using Letter = std::vector<bool>;

bool is_subset(const Letter& small, const Letter& large) {
  for (std::size_t i = 0; i < small.size(); ++i) {
    if (small[i] && !large[i]) return false;
  }
  return true;
}

// Absorb: a letter whose lines all share another letter says nothing more; of two equal letters
// the first stays.
void absorb(std::vector<Letter>& letters) {
  std::vector<Letter> kept;
  for (std::size_t c = 0; c < letters.size(); ++c) {
    bool redundant = std::none_of(letters[c].begin(), letters[c].end(), [](bool b) { return b; });
    for (std::size_t other = 0; other < letters.size() && !redundant; ++other) {
      if (other == c || !is_subset(letters[c], letters[other])) continue;
      redundant = letters[c] != letters[other] || other < c;
    }
    if (!redundant) kept.push_back(letters[c]);
  }
  letters = std::move(kept);
}

// Insert: every letter carried by both lines of a differing pair is split in two, one without
// each of them.
void insert(std::vector<Letter>& letters, std::size_t i, std::size_t j) {
  std::vector<Letter> split;
  for (const Letter& letter : letters) {
    if (letter[i] && letter[j]) {
      Letter without_i = letter, without_j = letter;
      without_i[i] = false;
      without_j[j] = false;
      split.push_back(std::move(without_i));
      split.push_back(std::move(without_j));
    } else {
      split.push_back(letter);
    }
  }
  letters = std::move(split);
}

bool share_another(const std::vector<Letter>& letters, std::size_t except, std::size_t i, std::size_t k) {
  for (std::size_t c = 0; c < letters.size(); ++c) {
    if (c != except && letters[c][i] && letters[c][k]) return true;
  }
  return false;
}

std::size_t count_letters(const std::vector<Letter>& letters, std::size_t line) {
  return static_cast<std::size_t>(
      std::count_if(letters.begin(), letters.end(), [&](const Letter& letter) { return letter[line]; }));
}

// Sweep: a line keeps a letter only if some other line shares that letter and no other
// (otherwise the letter links it to no one the other letters do not).
void sweep(std::vector<Letter>& letters) {
  for (std::size_t c = 0; c < letters.size(); ++c) {
    for (std::size_t i = 0; i < letters[c].size(); ++i) {
      if (!letters[c][i] || count_letters(letters, i) < 2) continue;
      bool needed = false;
      for (std::size_t k = 0; k < letters[c].size() && !needed; ++k) {
        needed = k != i && letters[c][k] && !share_another(letters, c, i, k);
      }
      if (!needed) letters[c][i] = false;
    }
  }
  absorb(letters);
}

std::string letter_name(std::size_t index) {
  constexpr std::string_view alphabet = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
  return std::string(1, alphabet[index % alphabet.size()]) + std::string(index / alphabet.size(), '\'');
}

// The lines carrying a letter, ascending: letters sort by their first line, then the next.
std::vector<std::size_t> members(const Letter& letter) {
  std::vector<std::size_t> lines;
  for (std::size_t i = 0; i < letter.size(); ++i) {
    if (letter[i]) lines.push_back(i);
  }
  return lines;
}

}  // namespace

std::vector<std::string> compact_letters(std::size_t lines,
                                         std::span<const std::pair<std::size_t, std::size_t>> differing) {
  for (const auto& [i, j] : differing) {
    if (i >= lines || j >= lines || i == j) {
      throw std::invalid_argument("compact_letters: pair (" + std::to_string(i) + ", " + std::to_string(j) +
                                  ") of " + std::to_string(lines) + " lines");
    }
  }
  std::vector<Letter> letters;
  if (lines > 0) letters.emplace_back(lines, true);
  for (const auto& [i, j] : differing) {
    insert(letters, i, j);
    absorb(letters);
  }
  sweep(letters);
  std::sort(letters.begin(), letters.end(), [](const Letter& a, const Letter& b) { return members(a) < members(b); });
  std::vector<std::string> result(lines);
  for (std::size_t c = 0; c < letters.size(); ++c) {
    for (std::size_t i = 0; i < lines; ++i) {
      if (letters[c][i]) result[i] += letter_name(c);
    }
  }
  return result;
}

}  // namespace growthuq
