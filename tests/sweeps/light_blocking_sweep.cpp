// Speed against error for lesson 05: the blended (dampening) shadow at every darkness
// against the light-blocking one. The reference recomputes the lighting per pixel with the
// light's visibility from the CPU ray cast: where the oracle says a ground pixel is
// shadowed it must look like the ground with the light off, elsewhere like the ground
// fully lit. Both halves come from the lesson itself (--set shadow=0, --set light=0), so
// only the shadow technique differs between a render and its reference.
//
//   light_blocking_sweep OUT [--quick] [--check]
//
// writes OUT.csv (tests/sweeps/plot_sweeps.py draws its plot). --quick renders fewer frames;
// --check exits 1 unless blocking matches the reference (off the shadow's edges) and every
// blended shadow is worse.
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

#include "geometry/shadow_oracle.h"
#include "gl/image.h"
#include "sweep_support.h"

using namespace stencil;
namespace fs = std::filesystem;

namespace {

const std::string kSize = "640x480";
const std::vector<double> kTimes = {1.0, 2.0, 3.0, 4.0};

struct Config {
  std::string label, settings;  // --variant and --set flags
  bool block;
  int darkness;  // tenths of the light a blended shadow removes
};

struct Row {
  Config config;
  double frameMs = 0, rms = 0, maxError = 0;
  double wrongPixels = 0;  // receiver pixels off by more than 5/255 in some channel, per frame
  long long triangles = 0, drawCalls = 0;
};

void run(const std::string& args) {
  runOrExit("light_blocking_sweep",
            std::string(LESSON_05) + " --headless --quiet --size " + kSize + " " + args);
}

struct Reference {
  std::vector<PixelClass> classes;
  Image colour;
};

Reference referenceAt(const fs::path& dir, double time) {
  const std::string t = " --time " + std::to_string(time);
  const fs::path oracle = dir / "oracle.png", lit = dir / "lit.png", unlit = dir / "unlit.png";
  run("--variant block" + t + " --oracle " + oracle.string() + " 2>/dev/null");
  run("--variant block --set shadow=0" + t + " --out " + lit.string());
  run("--variant block --set shadow=0 --set light=0" + t + " --out " + unlit.string());
  const Image raw = readPng(dir / "oracle.raw.png", 1);
  Reference r{{}, readPng(lit, 4)};
  const Image dark = readPng(unlit, 4);
  for (std::size_t i = 0; i < raw.pixels.size(); ++i) {
    r.classes.push_back(static_cast<PixelClass>(raw.pixels[i]));
    if (r.classes.back() == PixelClass::Shadowed)
      std::copy_n(&dark.pixels[4 * i], 4, &r.colour.pixels[4 * i]);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  int exitCode = 0;
  const auto commandLine = parseSweepCommandLine("light_blocking_sweep", argc, argv, exitCode);
  if (!commandLine) return exitCode;
  const fs::path out = commandLine->out, work = commandLine->work;
  const bool quick = commandLine->quick, check = commandLine->check;

  std::vector<Config> configs = {{"block", "--variant block", true, 0}};
  for (int d = 1; d <= 10; ++d)
    configs.push_back({"dampen " + std::to_string(d) + "/10",
                       "--variant dampen --set darkness=" + std::to_string(d), false, d});
  std::vector<Row> rows;
  for (const Config& c : configs) rows.push_back({c});

  const std::vector<double> times = quick ? std::vector<double>{1.0} : kTimes;
  for (double time : times) {
    std::cerr << "sweep: reference at t = " << time << "\n";
    const Reference ref = referenceAt(work, time);
    for (Row& row : rows) {
      const fs::path image = work / "render.png";
      run(row.config.settings + " --time " + std::to_string(time) + " --out " + image.string());
      const Image got = readPng(image, 4);
      double sum = 0;
      std::size_t n = 0, wrong = 0;
      for (std::size_t i = 0; i < ref.classes.size(); ++i) {
        if (ref.classes[i] != PixelClass::Lit && ref.classes[i] != PixelClass::Shadowed) continue;
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) {
          const int d = std::abs(int(got.pixels[4 * i + ch]) - int(ref.colour.pixels[4 * i + ch]));
          sum += double(d) * d;
          worst = std::max(worst, d);
        }
        ++n;
        wrong += worst > 5;
        row.maxError = std::max(row.maxError, double(worst));
      }
      row.rms += std::sqrt(sum / (3.0 * double(n))) / double(times.size());
      row.wrongPixels += double(wrong) / double(times.size());
    }
  }
  for (Row& row : rows) {
    const fs::path stats = work / "stats.json";
    run(row.config.settings + " --time 1 --stats --frames " + (quick ? "3" : "61") + " > " + stats.string());
    const LessonStats json = LessonStats::read(stats);
    row.frameMs = json.frameMs("mean");
    row.triangles = json.total("triangles");
    row.drawCalls = json.total("draw_calls");
    std::fprintf(stderr, "sweep: %-12s %7.3f ms  rms %6.2f  wrong px %8.1f\n", row.config.label.c_str(),
                 row.frameMs, row.rms, row.wrongPixels);
  }

  std::ofstream csv(out.string() + ".csv");
  csv << "method,darkness,frame_ms,rms_error,max_error,wrong_pixels,triangles,draw_calls\n";
  for (const Row& r : rows)
    csv << (r.config.block ? "block" : "dampen") << "," << r.config.darkness << "," << r.frameMs << ","
        << r.rms << "," << r.maxError << "," << r.wrongPixels << "," << r.triangles << "," << r.drawCalls
        << "\n";
  fs::remove_all(work);
  std::cerr << "sweep: wrote " << out.string() << ".csv\n";

  if (!check) return 0;
  // Blocking differs from the reference only on the shadow's edge pixels; each blend is
  // wrong on most of the shadow, whatever its darkness.
  double bestBlend = 1e9;
  for (const Row& r : rows)
    if (!r.config.block) bestBlend = std::min(bestBlend, r.wrongPixels);
  const Row& block = rows.front();
  const bool ok = block.wrongPixels < 0.1 * bestBlend;
  std::cerr << (ok ? "sweep check ok: " : "sweep check FAILED: ") << "blocking " << block.wrongPixels
            << " wrong pixels, the best blend " << bestBlend << "\n";
  return ok ? 0 : 1;
}
