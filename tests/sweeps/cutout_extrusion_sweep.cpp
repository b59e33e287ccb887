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
// writes OUT.csv and OUT.svg. --quick uses fewer configurations and frames; --check exits 1
// unless the three methods agree with the ray cast off its edges for every lattice, submit the
// same count-pass triangles, and the sphere's error falls as its tessellation grows.
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

// "oracle ok: R receiver pixels, S shadowed; D disagree, E of them on edges (...)"
void readOracle(const fs::path& log, Row& row) {
  const std::string text = readAll(log);
  const auto at = text.find("oracle ");
  long long receivers = 0, shadowed = 0, disagree = 0, onEdges = 0;
  if (at == std::string::npos ||
      std::sscanf(text.c_str() + text.find(':', at) + 1,
                  " %lld receiver pixels, %lld shadowed; %lld disagree, %lld of them on edges", &receivers,
                  &shadowed, &disagree, &onEdges) != 4)
    throw std::runtime_error("no oracle line in " + log.string());
  row.wrong = disagree;
  row.wrongOffEdges = disagree - onEdges;
  row.shadowed = shadowed;
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

// One scatter panel: x and y of each row, a colour per series, a label per point.
struct Panel {
  std::string title, xLabel, yLabel;
  std::vector<std::string> series;
  std::vector<std::string> colours;
  struct Point {
    double x, y;
    std::size_t series;
    std::string label;
  };
  std::vector<Point> points;
};

void writePanel(std::ofstream& out, const Panel& p, double left, double top, double width, double height) {
  double maxX = 0, maxY = 0;
  for (const auto& pt : p.points) maxX = std::max(maxX, pt.x), maxY = std::max(maxY, pt.y);
  maxX = maxX > 0 ? maxX * 1.1 : 1, maxY = maxY > 0 ? maxY * 1.15 : 1;
  const double bottom = top + height, right = left + width;
  const auto x = [&](double v) { return left + width * v / maxX; };
  const auto y = [&](double v) { return bottom - height * v / maxY; };
  out << "<text x='" << (left + right) / 2 << "' y='" << top - 8
      << "' text-anchor='middle' font-weight='bold'>" << p.title << "</text>\n"
      << "<line x1='" << left << "' y1='" << bottom << "' x2='" << right << "' y2='" << bottom
      << "' stroke='black'/>\n"
      << "<line x1='" << left << "' y1='" << bottom << "' x2='" << left << "' y2='" << top
      << "' stroke='black'/>\n"
      << "<text x='" << (left + right) / 2 << "' y='" << bottom + 32 << "' text-anchor='middle'>" << p.xLabel
      << "</text>\n<text x='" << left - 45 << "' y='" << (top + bottom) / 2 << "' transform='rotate(-90 "
      << left - 45 << " " << (top + bottom) / 2 << ")' text-anchor='middle'>" << p.yLabel << "</text>\n";
  for (int i = 0; i <= 4; ++i) {
    const double vx = maxX * i / 4, vy = maxY * i / 4;
    out << "<text x='" << x(vx) << "' y='" << bottom + 14 << "' text-anchor='middle'>"
        << (maxX >= 100 ? std::to_string(static_cast<long long>(std::round(vx)))
                        : std::to_string(std::round(vx * 10) / 10).substr(0, 4))
        << "</text>\n<text x='" << left - 5 << "' y='" << y(vy) + 4 << "' text-anchor='end'>"
        << (maxY >= 100 ? std::to_string(static_cast<long long>(std::round(vy)))
                        : std::to_string(std::round(vy * 10) / 10).substr(0, 4))
        << "</text>\n";
  }
  for (std::size_t s = 0; s < p.series.size(); ++s) {
    std::string path;
    for (const auto& pt : p.points)
      if (pt.series == s)
        path += (path.empty() ? "M" : " L") + std::to_string(x(pt.x)) + " " + std::to_string(y(pt.y));
    out << "<path d='" << path << "' fill='none' stroke='" << p.colours[s] << "'/>\n"
        << "<text x='" << left + 10 << "' y='" << top + 14.0 * static_cast<double>(s + 1)
        << "' text-anchor='start' fill='" << p.colours[s] << "'>" << p.series[s] << "</text>\n";
  }
  for (const auto& pt : p.points)
    out << "<circle cx='" << x(pt.x) << "' cy='" << y(pt.y) << "' r='3' fill='" << p.colours[pt.series]
        << "'/>\n<text x='" << x(pt.x) + 5 << "' y='" << y(pt.y) - 5 << "' font-size='9'>" << pt.label
        << "</text>\n";
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

  Panel methodsPanel{"Extrusion of the lattice (" + kSize + ")",
                     "count-pass triangles",
                     "fastest frame (ms)",
                     {"cpu", "matrix", "gpu"},
                     {"#d04020", "#208040", "#3060c0"},
                     {}};
  Panel spherePanel{"Flattened sphere against the true sphere (labels: slices)",
                    "fastest frame (ms)",
                    "wrong pixels",
                    {"flatten"},
                    {"#804090"},
                    {}};
  for (const Row& r : rows) {
    if (r.sweep == "methods") {
      const auto s =
          static_cast<std::size_t>(std::find(methods.begin(), methods.end(), r.method) - methods.begin());
      methodsPanel.points.push_back({static_cast<double>(r.countTriangles), r.frameMsMin, s,
                                     s == 0 ? std::to_string(r.holes) + "x" + std::to_string(r.holes) : ""});
    } else {
      spherePanel.points.push_back({r.frameMsMin, static_cast<double>(r.wrong), 0, std::to_string(r.slices)});
    }
  }
  std::ofstream svg(out.string() + ".svg");
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='1000' height='380' font-family='sans-serif' "
         "font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n";
  writePanel(svg, methodsPanel, 80, 40, 360, 270);
  writePanel(svg, spherePanel, 590, 40, 360, 270);
  svg << "</svg>\n";
  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv and .svg\n";

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
