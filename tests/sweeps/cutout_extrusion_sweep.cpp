// Speed against error for lesson 09, two sweeps in one run.
//
// Methods: the lattice's volume extruded on the CPU each frame, by one projective matrix on a
// static prism, and on the GPU from doubled vertices, for lattices with more and more holes
// (more border edges). Time per frame, triangles submitted in the count passes, and the error
// against the ray cast (pixels that disagree off its edges) on the same scene.
//
// Sphere: a sphere flattened into a cut-out silhouette at increasing tessellation, judged against
// the shadow of the true sphere (the oracle intersects the analytic sphere): wrong pixels against
// triangles and time.
//
//   cutout_extrusion_sweep OUT [--quick] [--check]
//
// writes OUT.csv (tests/sweeps/plot_sweeps.py draws its plot). --quick uses fewer
// configurations and frames; --check exits 1 unless the three methods agree with the ray cast
// off its edges for every lattice, submit the same count-pass triangles, and the sphere's error
// falls as its tessellation grows.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "sweep_support.h"

using namespace std::string_literals;
namespace fs = std::filesystem;

namespace {

const std::string kSize = "640x480";

struct Row {
  std::string sweep, method;
  int holes = 0, slices = 0;
  double frameMs = 0, frameMsMin = 0;  // mean and fastest of the frames after the first
  long long triangles = 0, countTriangles = 0, drawCalls = 0;
  long long wrong = 0, wrongOffEdges = 0, shadowed = 0;
};

// Runs the lesson; exit 1 is allowed where the oracle is expected to report disagreements.
void run(const std::string& args, bool oracleMayFail = false) {
  runOrExit("cutout_extrusion_sweep",
            std::string(LESSON_09) + " --headless --quiet --size " + kSize + " " + args, oracleMayFail);
}

// The oracle's count of wrong pixels, and of shadowed ones, from its log.
void readOracle(const fs::path& log, Row& row) {
  const OracleLine o = readOracleLine(log);
  row.wrong = o.disagree;
  row.wrongOffEdges = o.offEdges();
  row.shadowed = o.shadowed;
}

void measure(const fs::path& work, const std::string& settings, int frames, Row& row) {
  const fs::path log = work / "oracle.log", picture = work / "oracle.png", stats = work / "stats.json";
  run(settings + " --time 1 --oracle " + picture.string() + " 2> " + log.string(), true);
  readOracle(log, row);
  run(settings + " --time 1 --stats --frames " + std::to_string(frames) + " > " + stats.string());
  const LessonStats json = LessonStats::read(stats);
  row.frameMs = json.frameMs("mean");
  row.frameMsMin = json.frameMs("min");
  row.triangles = json.total("triangles");
  row.drawCalls = json.total("draw_calls");
  row.countTriangles = json.firstPass("count", "triangles");
  std::fprintf(stderr,
               "sweep: %-7s %-7s holes %2d slices %3d  %7.3f ms  %7lld tri (count %6lld)  wrong %5lld (%lld "
               "off edges)\n",
               row.sweep.c_str(), row.method.c_str(), row.holes, row.slices, row.frameMsMin, row.triangles,
               row.countTriangles, row.wrong, row.wrongOffEdges);
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("cutout_extrusion_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;
  const int frames = quick ? 3 : 61;

  std::vector<Row> rows;
  const std::vector<std::string> methods = {"cpu", "matrix", "gpu"};
  const std::vector<int> holes = quick ? std::vector<int>{3, 16} : std::vector<int>{1, 3, 6, 10, 16};
  for (const int n : holes)
    for (std::size_t m = 0; m < methods.size(); ++m) {
      Row row{"methods", methods[m], n};
      measure(work, "--variant " + methods[m] + " --set holes=" + std::to_string(n), frames, row);
      rows.push_back(row);
    }
  const std::vector<int> slices = quick
                                      ? std::vector<int>{6, 16, 64}
                                      : std::vector<int>{4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256};
  for (const int s : slices) {
    Row row{"sphere", "flatten", 0, s};
    measure(work, "--variant sphere --set analytic=1 --set slices=" + std::to_string(s), frames, row);
    rows.push_back(row);
  }

  std::ofstream csv(out.string() + ".csv");
  csv << "sweep,method,holes,slices,frame_ms,frame_ms_min,triangles,count_triangles,draw_calls,wrong_pixels,"
         "wrong_off_"
         "edges,"
         "shadowed_pixels\n";
  for (const Row& r : rows)
    csv << r.sweep << "," << r.method << "," << r.holes << "," << r.slices << "," << r.frameMs << ","
        << r.frameMsMin << "," << r.triangles << "," << r.countTriangles << "," << r.drawCalls << ","
        << r.wrong << "," << r.wrongOffEdges << "," << r.shadowed << "\n";

  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv\n";

  if (!check) return 0;
  bool ok = true;
  for (const int n : holes) {
    long long triangles = -1;
    for (const Row& r : rows) {
      if (r.sweep != "methods" || r.holes != n) continue;
      if (r.wrongOffEdges != 0) {
        std::cerr << "sweep check FAILED: " << r.method << " with " << n << "x" << n
                  << " holes: " << r.wrongOffEdges << " wrong pixels off the ray cast's edges\n";
        ok = false;
      }
      if (triangles >= 0 && r.countTriangles != triangles) {
        std::cerr << "sweep check FAILED: " << r.method << " submits " << r.countTriangles
                  << " count triangles, not " << triangles << "\n";
        ok = false;
      }
      triangles = r.countTriangles;
    }
  }
  const Row* coarse = nullptr;
  const Row* fine = nullptr;
  for (const Row& r : rows)
    if (r.sweep == "sphere") {
      if (!coarse) coarse = &r;
      fine = &r;
    }
  if (!(fine->wrong * 4 < coarse->wrong) || !(fine->countTriangles > coarse->countTriangles)) {
    std::cerr << "sweep check FAILED: the sphere at " << fine->slices << " slices has " << fine->wrong
              << " wrong pixels, at " << coarse->slices << " slices " << coarse->wrong << "\n";
    ok = false;
  }
  std::cerr << (ok ? "sweep check ok" : "sweep check FAILED")
            << ": methods agree with the ray cast; sphere error " << coarse->wrong << " -> " << fine->wrong
            << " wrong pixels from " << coarse->slices << " to " << fine->slices << " slices\n";
  return ok ? 0 : 1;
}
