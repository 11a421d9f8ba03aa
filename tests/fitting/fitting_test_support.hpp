// Shared helpers of the fitting tests: the NIST StRD reference files under data/ (format in their
// headers) and significant-digit comparison.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_paths.hpp"

namespace si::fit::testing {

struct StrdProblem {
  std::vector<std::string> names;
  Eigen::VectorXd start1, start2;  // empty entries ("-") for linear problems
  Eigen::VectorXd certified, certified_sd;
  std::map<std::string, double> stats;  // "rss", "rsd", "r2"
  Eigen::VectorXd x, y;
};

inline StrdProblem read_strd(const std::string& name) {
  const std::string path = std::string(SHELLINDENT_SOURCE_DIR) + "/tests/fitting/data/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  StrdProblem p;
  std::vector<double> s1, s2, cert, sd, xs, ys;
  std::string line;
  bool data = false;
  auto number = [](const std::string& t) { return t == "-" ? NAN : std::stod(t); };
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    std::string key;
    is >> key;
    if (data) {
      std::string xt;
      is >> xt;
      ys.push_back(std::stod(key));
      xs.push_back(std::stod(xt));
    } else if (key == "data") {
      data = true;
    } else if (key == "param") {
      std::string n, a, b, c, d;
      is >> n >> a >> b >> c >> d;
      p.names.push_back(n);
      s1.push_back(number(a));
      s2.push_back(number(b));
      cert.push_back(number(c));
      sd.push_back(number(d));
    } else {
      std::string v;
      is >> v;
      p.stats[key] = std::stod(v);
    }
  }
  auto vec = [](const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())).eval();
  };
  p.start1 = vec(s1);
  p.start2 = vec(s2);
  p.certified = vec(cert);
  p.certified_sd = vec(sd);
  p.x = vec(xs);
  p.y = vec(ys);
  return p;
}

// Log relative error, the "number of significant digits in agreement" of McCullough (1999,
// "Assessing the reliability of statistical software", Am. Stat. 53) used to score the StRD.
inline double agreeing_digits(double computed, double certified) {
  if (computed == certified) return 16.0;
  if (certified == 0.0) return -std::log10(std::abs(computed));
  return -std::log10(std::abs(computed - certified) / std::abs(certified));
}

}  // namespace si::fit::testing
