// The command line every sweep takes: OUT [--quick] [--check], and a scratch folder of its own.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

struct SweepCommandLine {
  std::filesystem::path out;   // OUT.csv and OUT.svg are written beside it
  std::filesystem::path work;  // renders go here, one folder per run
  bool quick = false;          // fewer frames and points, for ctest
  bool check = false;          // exit 1 unless the page's claim holds
};

// nullopt with exitCode set for --help (0) or bad input (2, one line on stderr).
inline std::optional<SweepCommandLine> parseSweepCommandLine(const std::string& name, int argc, char** argv,
                                                             int& exitCode) {
  if (argc < 2 || std::string(argv[1]) == "--help") {
    std::cout << "usage: " << name << " OUT [--quick] [--check]   (writes OUT.csv and OUT.svg)\n";
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
