// Lesson 14's benchmark: OpenCSG's box minus a grid of spheres, 1x1 to 7x7 (2 to 50 primitives,
// one product), its box minus a 3x3x3 grid of spheres (28), its cube rack (a box minus 343 boxes,
// layered only, one frame) and the torus minus a box (concave, convexity 2), drawn by Goldfeather, layered
// Goldfeather (each with and without the occlusion-query early stop) and SCS, in one run: the time
// per frame, the lesson's pass counts and, for each, the pixels the CSG ray cast disagrees with off
// edges. Writes OUT.csv; tests/sweeps/plot_sweeps.py draws OUT.svg from it. --check: every method
// that draws the solid agrees with the ray cast (SCS refuses the concave torus), and the pass counts
// are the formulas'.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "sweep_support.h"

namespace fs = std::filesystem;

namespace {

constexpr const char* kSize = "320x240";

struct Method {
  std::string name, settings;
};

struct Row {
  std::string scene, method;
  int primitives = 0;
  double frameMs = 0;
  long long passes = 0, parity = 0, wrong = 0;
};

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("csg_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;

  const std::vector<Method> methods = {
      {"goldfeather", "--set method=1"}, {"goldfeather+queries", "--set method=1 --set queries=1"},
      {"layered", "--set method=2"},     {"layered+queries", "--set method=2 --set queries=1"},
      {"scs", "--set method=3"},
  };
  const std::vector<int> sides = quick ? std::vector<int>{1, 3} : std::vector<int>{1, 2, 3, 4, 5, 6, 7};
  std::vector<Row> rows;
  bool ok = true;
  const auto measure = [&](const std::string& scene, const std::string& sceneSettings, int primitives,
                           const Method& m, int frames = 5) {
    const fs::path stats = work / "stats.json";
    runOrExit("csg_sweep", std::string(LESSON_14) + " --headless --quiet --size " + kSize + " --time 1 " +
                               sceneSettings + " " + m.settings + " --set oracle=1 --stats --frames " +
                               std::to_string(quick ? 2 : frames) + " > " + stats.string());
    const LessonStats json = LessonStats::read(stats);
    const auto count = [&](const char* key) { return std::max(0LL, json.count(key)); };  // absent: 0
    Row r{scene, m.name, primitives};
    r.frameMs = json.frameMs("mean");
    r.passes = count("select_passes") + count("parity_passes") + count("far_passes") + count("merge_passes") +
               count("subtraction_passes") + count("clip_passes");
    r.parity = count("parity_passes");
    r.wrong = count("oracle_primitive_disagreements") + count("oracle_depth_disagreements") -
              count("oracle_on_edges");
    std::fprintf(stderr, "sweep: %-6s %2d %-20s %9.2f ms %6lld passes %6lld wrong\n", scene.c_str(),
                 primitives, m.name.c_str(), r.frameMs, r.passes, r.wrong);
    rows.push_back(r);
    return r;
  };
  for (int side : sides) {
    const int n = side * side + 1;
    for (const Method& m : methods) {
      const Row r = measure("grid", "--set scene=4 --set grid=" + std::to_string(side), n, m);
      if (r.wrong != 0) ok = false;
      // Goldfeather with a bound of 1 on one product of n: n (n - 1) parity passes; SCS has none.
      if (m.name == "goldfeather" && r.parity != static_cast<long long>(n) * (n - 1)) ok = false;
    }
  }
  for (const Method& m : methods) {
    if (m.name == "scs") continue;  // SCS refuses the concave torus (exit 2)
    const Row r = measure("torus", "--variant goldfeather-torus", 2, m);
    if (r.wrong > 0) ok = false;
  }

  // OpenCSG's 3x3x3 grid: a box minus 27 spheres, each face cut by nine of them.
  for (const Method& m : methods)
    if (measure("grid3", "--set scene=8", 28, m).wrong != 0) ok = false;
  // The cube rack (a box minus 343 boxes) by the layered methods alone: Goldfeather's bound of one
  // takes n (n - 1) = 117,306 parity passes and SCS a sequence of as many entries, minutes a frame.
  if (!quick)
    for (const Method& m : methods)
      if (m.name.starts_with("layered"))
        if (measure("rack", "--set scene=7", 344, m, 1).wrong != 0) ok = false;

  std::ofstream csv(out.string() + ".csv");
  csv << "scene,primitives,method,frame_ms,passes,parity_passes,wrong_pixels_off_edges\n";
  for (const Row& r : rows)
    csv << r.scene << "," << r.primitives << "," << r.method << "," << r.frameMs << "," << r.passes << ","
        << r.parity << "," << r.wrong << "\n";
  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv\n";
  if (!check) return 0;
  std::cerr
      << (ok ? "sweep check ok: " : "sweep check FAILED: ")
      << "every method agrees with the ray cast on the grid and every method but SCS (which refuses it) on the torus, Goldfeather's "
         "parity passes are n(n - 1)\n";
  return ok ? 0 : 1;
}
