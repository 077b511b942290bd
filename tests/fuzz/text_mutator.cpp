#include "fuzz/text_mutator.hpp"

#include <cctype>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <vector>

namespace granule::fuzz {

namespace {

using Random = std::mt19937_64;

std::size_t pick(Random& random, std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random); }

// What a damaged or hostile file may hold where a number is expected.
const char* const kSpecialNumbers[] = {"nan",  "NaN",  "inf", "-inf", "-1",   "1e308", "1e999", "-0", "0",
                                       "1e-320", "99999999999999999999999", "18446744073709551616",
                                       "9223372036854775808", "\"x\"", "", "0x10", "1,2", "--1", "1e", "2147483648"};

// Where the numbers are: maximal runs of [-+.0-9eE] that hold a digit.
std::vector<std::pair<std::size_t, std::size_t>> numbers_in(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> found;
  const auto in_number = [](char ch) { return (ch >= '0' && ch <= '9') || ch == '-' || ch == '+' || ch == '.' || ch == 'e' || ch == 'E'; };
  for (std::size_t k = 0; k < text.size();) {
    if (!in_number(text[k])) {
      ++k;
      continue;
    }
    std::size_t end = k;
    bool digit = false;
    for (; end < text.size() && in_number(text[end]); ++end) digit = digit || (text[end] >= '0' && text[end] <= '9');
    // "e" alone inside a word (a key like "seconds") is no number.
    if (digit && (k == 0 || !std::isalpha(static_cast<unsigned char>(text[k - 1])))) found.emplace_back(k, end - k);
    k = end;
  }
  return found;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '\n') {
      lines.push_back(text.substr(start, k + 1 - start));
      start = k + 1;
    }
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line;
  return text;
}

std::string mutate_bytes(std::string text, Random& random, std::string& what) {
  if (text.empty()) {
    what += "; empty file kept";
    return text;
  }
  const std::size_t at = pick(random, text.size());
  switch (pick(random, 4)) {
    case 0:
      text[at] = static_cast<char>(text[at] ^ (1 << pick(random, 8)));
      what += "; bit flipped at byte " + std::to_string(at);
      break;
    case 1: {
      const char bytes[] = {'\0', ',', '"', '\n', '{', '[', ':', '-', '9', '\xff'};
      text[at] = bytes[pick(random, sizeof bytes)];
      what += "; byte " + std::to_string(at) + " changed";
      break;
    }
    case 2:
      text.insert(at, pick(random, 2) == 0 ? std::string(",") : std::string("\n1,2,3\n"));
      what += "; bytes inserted at " + std::to_string(at);
      break;
    default:
      text.resize(at);
      what += "; cut to " + std::to_string(at) + " bytes";
  }
  return text;
}

std::string mutate_lines(const std::string& text, Random& random, std::string& what) {
  std::vector<std::string> lines = lines_of(text);
  if (lines.empty()) return text;
  const std::size_t a = pick(random, lines.size());
  const std::size_t b = pick(random, lines.size());
  switch (pick(random, 3)) {
    case 0:
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(a));
      what += "; line " + std::to_string(a + 1) + " deleted";
      break;
    case 1:
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(b), lines[a]);
      what += "; line " + std::to_string(a + 1) + " copied before line " + std::to_string(b + 1);
      break;
    default:
      std::swap(lines[a], lines[b]);
      what += "; lines " + std::to_string(a + 1) + " and " + std::to_string(b + 1) + " swapped";
  }
  return joined(lines);
}

std::string mutate_number(std::string text, Random& random, std::string& what) {
  const auto numbers = numbers_in(text);
  if (numbers.empty()) return mutate_bytes(text, random, what);
  const auto [at, length] = numbers[pick(random, numbers.size())];
  const std::string replacement = kSpecialNumbers[pick(random, std::size(kSpecialNumbers))];
  what += "; number " + text.substr(at, length) + " at byte " + std::to_string(at) + " replaced by " + replacement;
  text.replace(at, length, replacement);
  return text;
}

// Every object member of `value` (nested ones included), as (object, key).
void members(nlohmann::json& value, std::vector<std::pair<nlohmann::json*, std::string>>& out) {
  if (value.is_object()) {
    for (auto& [key, inner] : value.items()) {
      out.emplace_back(&value, key);
      members(inner, out);
    }
  } else if (value.is_array()) {
    for (nlohmann::json& inner : value) members(inner, out);
  }
}

std::string mutate_json(const std::string& text, Random& random, std::string& what) {
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  std::vector<std::pair<nlohmann::json*, std::string>> found;
  if (!json.is_discarded()) members(json, found);
  if (found.empty()) return mutate_number(text, random, what);
  auto& [object, key] = found[pick(random, found.size())];
  switch (pick(random, 4)) {
    case 0: {
      const nlohmann::json others[] = {nullptr, true, "x", "", 5, -1, 1.5, -0.0, 1e308, nlohmann::json::array(),
                                       nlohmann::json::object(), {1, 2}, 18446744073709551615ull, "finished",
                                       "inelastic collapse", std::string(2000, 'a')};
      const nlohmann::json& other = others[pick(random, std::size(others))];
      what += "; \"" + key + "\" set to " + other.dump().substr(0, 40);
      (*object)[key] = other;
      break;
    }
    case 1:
      object->erase(key);
      what += "; \"" + key + "\" deleted";
      break;
    case 2: {
      nlohmann::json moved = (*object)[key];
      object->erase(key);
      (*object)[key + "_renamed"] = std::move(moved);
      what += "; \"" + key + "\" renamed";
      break;
    }
    default:
      (*object)["unknown_key"] = 1;
      what += "; a key added beside \"" + key + "\"";
  }
  return json.dump(2) + "\n";
}

}  // namespace

std::string mutate_text(const std::string& text, std::uint64_t seed, std::uint64_t index, std::string& what) {
  Random random(seed * 0x9E3779B97F4A7C15ull + index);
  std::string mutant = text;
  what = "text mutant";
  const std::size_t rounds = 1 + (pick(random, 4) == 0 ? 1 + pick(random, 2) : 0);
  for (std::size_t round = 0; round < rounds; ++round) {
    switch (pick(random, 5)) {
      case 0: mutant = mutate_bytes(mutant, random, what); break;
      case 1: mutant = mutate_lines(mutant, random, what); break;
      case 2:
      case 3: mutant = mutate_number(mutant, random, what); break;
      default: mutant = mutate_json(mutant, random, what);
    }
  }
  return mutant;
}

std::string write_text_mutant(const std::string& original, const std::string& mutant, std::uint64_t seed,
                              std::uint64_t index) {
  std::ifstream in(original, std::ios::binary);
  if (!in) throw std::runtime_error("mutator: cannot read " + original);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::string what;
  const std::string mutated = mutate_text(text, seed, index, what);
  std::ofstream out(mutant, std::ios::binary | std::ios::trunc);
  out << mutated;
  if (!out.flush()) throw std::runtime_error("mutator: cannot write " + mutant);
  return what;
}

}  // namespace granule::fuzz
