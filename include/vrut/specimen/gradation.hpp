#pragma once
// Mass gradations: the three of docs/method.md section 2, or a user CSV file of
// "sieve_mm,percent_passing" lines. Host-only.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct Gradation {
  std::string name;
  std::vector<double> sieve_mm;  // strictly decreasing
  std::vector<double> passing;   // percent passing by mass, non-increasing, 100 at the largest sieve

  // Percent passing at size d (mm), linear between sieves, 100 above the largest.
  double passing_at(double d) const {
    if (d >= sieve_mm.front()) return 100.0;
    for (std::size_t i = 1; i < sieve_mm.size(); ++i)
      if (d >= sieve_mm[i]) {
        const double f = (d - sieve_mm[i]) / (sieve_mm[i - 1] - sieve_mm[i]);
        return passing[i] + f * (passing[i - 1] - passing[i]);
      }
    throw std::out_of_range("size " + std::to_string(d) + " mm is below the smallest sieve of gradation " + name);
  }
};

// Checks the rules every gradation must follow; `where(i)` names row i in messages.
template <class Where>
void validate_gradation(const Gradation& g, Where where) {
  if (g.sieve_mm.size() < 2) throw std::invalid_argument(g.name + ": a gradation needs at least two sieves");
  for (std::size_t i = 0; i < g.sieve_mm.size(); ++i) {
    if (!(g.sieve_mm[i] > 0.0) || !std::isfinite(g.sieve_mm[i]))
      throw std::invalid_argument(where(i) + ": sieve size must be positive, got " + std::to_string(g.sieve_mm[i]));
    if (!(g.passing[i] >= 0.0 && g.passing[i] <= 100.0))
      throw std::invalid_argument(where(i) + ": percent passing must lie within 0..100, got " +
                                  std::to_string(g.passing[i]));
    if (i > 0 && !(g.sieve_mm[i] < g.sieve_mm[i - 1]))
      throw std::invalid_argument(where(i) + ": sieve sizes must decrease from line to line");
    if (i > 0 && g.passing[i] > g.passing[i - 1])
      throw std::invalid_argument(where(i) + ": percent passing must not increase as the sieves get smaller");
  }
  if (g.passing.front() != 100.0)
    throw std::invalid_argument(where(0) + ": the largest sieve must pass 100 %, got " + std::to_string(g.passing.front()));
}

// Gradations 1#, 2# (the reference mix) and 3# of docs/method.md section 2.
inline Gradation builtin_gradation(int number) {
  const std::vector<double> sieves{19.0, 16.0, 13.2, 9.5, 4.75, 2.36};
  switch (number) {
    case 1: return {"1", sieves, {100, 100, 92, 80, 62, 48}};
    case 2: return {"2", sieves, {100, 95, 84, 70, 48, 34}};
    case 3: return {"3", sieves, {100, 90, 76, 60, 34, 20}};
    default: throw std::invalid_argument("unknown gradation '" + std::to_string(number) + "' (built in: 1, 2, 3)");
  }
}

// Parses "sieve_mm,percent_passing" lines (a header line of that text, blank
// lines and lines starting with # are skipped). Errors (std::invalid_argument)
// name the line; `path` names the source in them.
inline Gradation parse_gradation_csv(std::istream& in, const std::string& path) {
  Gradation g;
  g.name = path;
  std::vector<int> line_of;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    line.erase(std::remove(line.begin(), line.end(), '\r'), line.end());
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    if (line.find("sieve") != std::string::npos) continue;  // header
    std::stringstream ss(line);
    std::string a, b, rest;
    if (!std::getline(ss, a, ',') || !std::getline(ss, b, ',') || std::getline(ss, rest, ','))
      throw std::invalid_argument(path + ":" + std::to_string(number) + ": expected 'sieve_mm,percent_passing', got '" +
                                  line + "'");
    double d, p;
    try {
      std::size_t used_a, used_b;
      d = std::stod(a, &used_a);
      p = std::stod(b, &used_b);
      if (a.find_first_not_of(" \t", used_a) != std::string::npos ||
          b.find_first_not_of(" \t", used_b) != std::string::npos)
        throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw std::invalid_argument(path + ":" + std::to_string(number) + ": not two numbers: '" + line + "'");
    }
    g.sieve_mm.push_back(d);
    g.passing.push_back(p);
    line_of.push_back(number);
  }
  if (g.sieve_mm.empty())
    throw std::invalid_argument(path + ": no sieve lines (a header alone is no gradation): give at least two "
                                "'sieve_mm,percent_passing' lines");
  validate_gradation(g, [&](std::size_t i) { return path + ":" + std::to_string(line_of[i]); });
  return g;
}

// Reads a gradation CSV file (parse_gradation_csv).
inline Gradation read_gradation_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot open gradation file '" + path + "'");
  return parse_gradation_csv(in, path);
}

// "1", "2", "3" or a file name. A name that is neither says both, so that
// "7" reads as no such mix rather than only as a missing file.
inline Gradation gradation_from_name(const std::string& name) {
  if (name == "1" || name == "2" || name == "3") return builtin_gradation(std::stoi(name));
  if (!std::ifstream(name))
    throw std::invalid_argument("gradation '" + name +
                                "' is neither a built-in mix (1, 2 or 3) nor a readable CSV file "
                                "(lines 'sieve_mm,percent_passing')");
  return read_gradation_csv(name);
}

}  // namespace vrut
