// What every sweep shares: its command line (OUT [--quick] [--check]) and scratch folder,
// running its lesson, and reading the lesson's --stats back.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "../lesson_stats.h"

using stencil::testing::LessonStats;

struct SweepCommandLine {
  std::filesystem::path out;   // OUT.csv is written beside it
  std::filesystem::path work;  // renders go here, one folder per run
  bool quick = false;          // fewer frames and points, for ctest
  bool check = false;          // exit 1 unless the page's claim holds
};

// nullopt with exitCode set for --help (0) or bad input (2, one line on stderr).
inline std::optional<SweepCommandLine> parseSweepCommandLine(const std::string& name, int argc, char** argv,
                                                             int& exitCode) {
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::cout << "usage: " << name << " OUT [--quick] [--check]   (writes OUT.csv)\n";
    exitCode = argc < 2 ? 2 : 0;
    return std::nullopt;
  }
  SweepCommandLine cl;
  cl.out = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick")
      cl.quick = true;
    else if (a == "--check")
      cl.check = true;
    else {
      std::cerr << name << ": unknown flag '" << a << "'\n";
      exitCode = 2;
      return std::nullopt;
    }
  }
  cl.work = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(getpid()));
  std::filesystem::create_directories(cl.work);
  std::filesystem::create_directories(std::filesystem::absolute(cl.out).parent_path());
  return cl;
}

// Runs a lesson command line; any other exit than 0 (or 1 where an --oracle run may report
// disagreements) ends the sweep, with 77 passed on so ctest reports a missing context as skipped.
inline void runOrExit(const std::string& sweep, const std::string& command, bool oracleMayFail = false) {
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 0 || (oracleMayFail && code == 1)) return;
  std::cerr << sweep << ": failed (" << status << "): " << command << "\n";
  std::exit(code == 77 ? 77 : 1);
}

inline std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What a lesson's --oracle line says: "oracle ok: R receiver pixels, S shadowed; D disagree, E of
// them on edges (...)". Throws std::runtime_error when the log holds no such line.
struct OracleLine {
  long long receivers = 0, shadowed = 0, disagree = 0, onEdges = 0;
  long long offEdges() const { return disagree - onEdges; }
};
inline OracleLine readOracleLine(const std::filesystem::path& log) {
  const std::string text = readAll(log);
  const auto at = text.find("oracle ");
  OracleLine o;
  if (at == std::string::npos ||
      std::sscanf(text.c_str() + text.find(':', at) + 1,
                  " %lld receiver pixels, %lld shadowed; %lld disagree, %lld of them on edges", &o.receivers,
                  &o.shadowed, &o.disagree, &o.onEdges) != 4)
    throw std::runtime_error("no oracle line in " + log.string());
  return o;
}
