// Lesson 16's benchmark, two sweeps in one run.
//
// Methods: McGuire et al. (z-pass or z-fail per caster by its case), Everitt and Kilgard (always
// z-fail with full caps), Lengyel (z-pass unless a caster is in the occlusion pyramid, then full
// z-fail for all) and z-pass alone, on the same scene along the same camera path: three views
// (outside every shadow; the eye in the sphere's shadow looking away; looking up past the sphere)
// at three moments of the moving casters. Per run: triangles submitted in the shadow passes,
// volume fragments in front of the scene (samples passed in the shadow passes), every fragment
// the volumes rasterize (the lesson's fill pass), the fastest frame and the pixels that disagree
// with the ray cast off its edges.
//
// Tessellation: the sphere's volume triangles (sides, dark cap, light cap) as its slices grow,
// in each of its three cases, for McGuire et al. and Lengyel: the paper's O(s), O(s), O(f)
// against O(s), O(f), O(f).
//
//   fast_shadows_sweep OUT [--quick] [--check]
//
// writes OUT.csv (tests/sweeps/plot_sweeps.py draws its plot). --check exits 1 unless the three
// robust methods agree with the ray cast off its edges everywhere (up to two grazing pixels),
// z-pass alone does not with the eye in a shadow, and the sphere's triangles grow as the paper
// says (linearly: at most 1.5 times the slice ratio; quadratically: at least half its square).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "sweep_support.h"

namespace fs = std::filesystem;

namespace {

const std::string kSize = "640x480";
constexpr long long kGrazingPixels = 2;  // wrong pixels off the ray cast's edges a robust method may have
const std::vector<std::string> kMethods = {"mcguire", "everitt-kilgard", "lengyel", "zpass"};
const std::vector<std::string> kViews = {"system", "eye-in-shadow", "looking-up"};

struct Row {
  std::string sweep, method, view;
  double time = 0;
  int slices = 0;
  double frameMsMin = 0;
  long long shadowTriangles = 0, volumeFragments = 0, rasterized = 0, wrongOffEdges = 0;
  long long sphereSides = 0, sphereDarkCap = 0, sphereLightCap = 0, sphereCase = 0;
  long long sphere() const { return sphereSides + sphereDarkCap + sphereLightCap; }
};

void run(const std::string& args, bool oracleMayFail = false) {
  runOrExit("fast_shadows_sweep", std::string(LESSON_16) + " --headless --quiet --size " + kSize + " " + args,
            oracleMayFail);
}

std::string settings(const Row& r) {
  const auto m = std::find(kMethods.begin(), kMethods.end(), r.method) - kMethods.begin();
  char time[16];
  std::snprintf(time, sizeof time, "%.2f", r.time);
  return "--variant " + r.view + " --set method=" + std::to_string(m) +
         (r.slices ? " --set slices=" + std::to_string(r.slices) : "") + " --time " + time;
}

void measureMethod(const fs::path& work, int frames, Row& row) {
  const fs::path log = work / "oracle.log", stats = work / "stats.json";
  run(settings(row) + " --oracle " + (work / "oracle.png").string() + " 2> " + log.string(), true);
  row.wrongOffEdges = readOracleLine(log).offEdges();
  // The counts from one frame at the row's time, with the fill pass; the time from frames
  // without it (they run on past the row's time, 1/60 s apart).
  run(settings(row) + " --set fill=1 --stats > " + stats.string());
  const LessonStats json = LessonStats::read(stats);
  row.shadowTriangles = json.passTotal("shadows", "triangles");
  row.volumeFragments = json.passTotal("shadows", "samples_passed");
  row.rasterized = json.passTotal("volume-fill", "samples_passed");
  run(settings(row) + " --stats --frames " + std::to_string(frames) + " > " + stats.string());
  row.frameMsMin = LessonStats::read(stats).frameMs("min");
  std::fprintf(
      stderr,
      "sweep: %-15s %-13s t %.2f  %8.3f ms  %6lld triangles  %8lld fragments, %8lld rasterized  %lld wrong\n",
      row.method.c_str(), row.view.c_str(), row.time, row.frameMsMin, row.shadowTriangles,
      row.volumeFragments, row.rasterized, row.wrongOffEdges);
}

void measureSphere(const fs::path& work, Row& row) {
  const fs::path stats = work / "stats.json";
  run(settings(row) + " --stats > " + stats.string());
  const LessonStats json = LessonStats::read(stats);
  row.sphereCase = json.count("case.sphere");
  row.sphereSides = json.count("sides.sphere");
  row.sphereDarkCap = json.count("dark_cap.sphere");
  row.sphereLightCap = json.count("light_cap.sphere");
  std::fprintf(
      stderr, "sweep: sphere %3d slices, case %lld, %-8s sides %5lld dark cap %5lld light cap %5lld\n",
      row.slices, row.sphereCase, row.method.c_str(), row.sphereSides, row.sphereDarkCap, row.sphereLightCap);
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("fast_shadows_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;
  const int frames = quick ? 2 : 31;
  const std::vector<double> times = quick ? std::vector<double>{1.0} : std::vector<double>{1.0, 2.5, 4.0};
  const std::vector<int> slices = quick ? std::vector<int>{16, 64} : std::vector<int>{16, 32, 64, 128};

  std::vector<Row> rows;
  for (const std::string& view : kViews)
    for (double t : times)
      for (const std::string& method : kMethods) {
        Row row{"methods", method, view, t};
        measureMethod(work, frames, row);
        rows.push_back(row);
      }
  for (const std::string& view : kViews)
    for (int s : slices)
      for (const std::string method : {"mcguire", "lengyel"}) {
        Row row{"tessellation", method, view, 1.0, s};
        measureSphere(work, row);
        rows.push_back(row);
      }

  std::ofstream csv(out.string() + ".csv");
  csv << "sweep,method,view,time,slices,frame_ms_min,shadow_triangles,volume_fragments,volume_fragments_"
         "rasterized,"
         "wrong_off_edges,sphere_case,sphere_sides,sphere_dark_cap,sphere_light_cap\n";
  for (const Row& r : rows)
    csv << r.sweep << "," << r.method << "," << r.view << "," << r.time << "," << r.slices << ","
        << r.frameMsMin << "," << r.shadowTriangles << "," << r.volumeFragments << "," << r.rasterized << ","
        << r.wrongOffEdges << "," << r.sphereCase << "," << r.sphereSides << "," << r.sphereDarkCap << ","
        << r.sphereLightCap << "\n";

  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv\n";

  if (!check) return 0;
  bool ok = true;
  for (const Row& r : rows) {
    if (r.sweep != "methods") continue;
    const bool robust = r.method != "zpass";
    // A face almost edge-on to the light meets its own silhouette's side face at its own depth:
    // at 640x480 a pixel there may go either way (docs/16-fast-robust-shadows.md).
    if (robust && r.wrongOffEdges > kGrazingPixels) {
      std::cerr << "sweep check FAILED: " << r.method << " in " << r.view << " at t " << r.time << ": "
                << r.wrongOffEdges << " wrong pixels\n";
      ok = false;
    }
    if (!robust && r.view != "system" && r.wrongOffEdges == 0) {
      std::cerr << "sweep check FAILED: z-pass alone agrees with the ray cast in " << r.view << "\n";
      ok = false;
    }
  }
  // Growth of the sphere's triangles from the fewest to the most slices, per case and method.
  const double ratio = double(slices.back()) / double(slices.front());
  for (const std::string& view : kViews)
    for (const std::string method : {"mcguire", "lengyel"}) {
      const Row *fewest = nullptr, *most = nullptr;
      for (const Row& r : rows)
        if (r.sweep == "tessellation" && r.view == view && r.method == method) {
          if (!fewest) fewest = &r;
          most = &r;
        }
      const double growth = double(most->sphere()) / double(fewest->sphere());
      // McGuire: O(f) only in case 3 (the light cap); Lengyel: O(f) once any caster is in the pyramid.
      const bool quadratic = method == "mcguire" ? most->sphereCase == 3 : view != "system";
      const bool holds = quadratic ? growth >= 0.5 * ratio * ratio : growth <= 1.5 * ratio;
      std::cerr << "sweep: sphere in case " << most->sphereCase << ", " << method << ": triangles x" << growth
                << " for slices x" << ratio << (quadratic ? " (O(f))" : " (O(s))") << "\n";
      if (!holds) {
        std::cerr << "sweep check FAILED: that is not " << (quadratic ? "O(f)" : "O(s)") << "\n";
        ok = false;
      }
    }
  std::cerr << (ok ? "sweep check ok" : "sweep check FAILED") << "\n";
  return ok ? 0 : 1;
}
