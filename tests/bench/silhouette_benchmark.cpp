// Silhouette extraction against a plain memory scan of the same data (Google Benchmark).
//
// mesh: facesLight (every triangle's three indices and positions: does it face the light?) then
// possibleSilhouetteEdges (every edge of the prepared caster's adjacency: do its two faces disagree?), on
// welded spheres and tori of about 1k to 1M triangles. prepared: the same edges from a
// SilhouetteCaster (face normals and first corners precomputed once, streamed by the facing pass;
// each edge's two faces read once against one-byte flags). scan: the arrays the mesh version
// reads (indices, positions, edges) summed as 32-bit words, nothing else; scan-prepared: the same
// for the arrays the prepared version streams (the six per-face floats and the edges' faces).
// The ratios say how far from memory-bound each extraction is. The halves are timed apart too
// (faces/edges: the mesh version's two calls; facing/edgepass: the prepared version's), and
// prepare: building the SilhouetteCaster, once per caster.
//
//   silhouette_benchmark [--quick] [--table FILE.md] [--raw FILE.csv] [benchmark flags]
//
// --quick: the three smallest sizes only, and two checks: every silhouette is a set of closed
// loops (each vertex leaves it as often as it enters it), and the prepared version gives the
// mesh version's edges; exit 1 if not. --table writes the results as a Markdown table
// (triangles, ns per triangle, GB/s, ratios to the scans); --raw the CPU time of every repetition
// of every benchmark as CSV.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geometry/dual_silhouette.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

struct Size {
  const char* name;
  int sphereSlices, sphereStacks;  // 2 * slices * (stacks - 1) triangles
  int torusMajor, torusMinor;      // 2 * major * minor triangles
};
constexpr Size sizes[] = {
    {"1k", 32, 17, 32, 16},      {"4k", 64, 33, 64, 32},       {"16k", 128, 65, 128, 64},
    {"64k", 256, 129, 256, 128}, {"256k", 512, 257, 512, 256}, {"1M", 1024, 513, 1024, 512},
};

// Built once per shape and size, outside the timed loops.
const PreparedCaster& caster(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<PreparedCaster>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) {
    const Mesh mesh = shape == "sphere" ? makeSphere(1.0f, size.sphereSlices, size.sphereStacks)
                                        : makeTorus(1.0f, 0.3f, size.torusMajor, size.torusMinor);
    slot = std::make_unique<PreparedCaster>(prepareCaster(mesh));
  }
  return *slot;
}

const SilhouetteCaster& silhouetteCaster(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<SilhouetteCaster>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) {
    const PreparedCaster& c = caster(shape, size);
    slot = std::make_unique<SilhouetteCaster>(prepareSilhouettes(c.mesh, c.adjacency));
  }
  return *slot;
}

const DualSilhouettes& dualTree(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<DualSilhouettes>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) slot = std::make_unique<DualSilhouettes>(silhouetteCaster(shape, size));
  return *slot;
}

// The sum of an array's bytes as 32-bit words, four running sums so that the loop is bound by
// loads, not by one addition's latency.
template <typename T>
std::uint32_t sumWords(const std::vector<T>& v) {
  static_assert(sizeof(T) % 4 == 0);
  const std::size_t words = v.size() * sizeof(T) / 4;
  const auto* p = reinterpret_cast<const std::uint32_t*>(v.data());
  std::uint32_t s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  std::size_t i = 0;
  for (; i + 4 <= words; i += 4) {
    s0 += p[i];
    s1 += p[i + 1];
    s2 += p[i + 2];
    s3 += p[i + 3];
  }
  for (; i < words; ++i) s0 += p[i];
  return s0 + s1 + s2 + s3;
}

// What both benchmarks read, in bytes: indices and positions (facesLight), edges (possibleSilhouetteEdges).
std::int64_t bytesRead(const PreparedCaster& c) {
  return static_cast<std::int64_t>(c.mesh.indices.size() * sizeof(std::uint32_t) +
                                   c.mesh.positions.size() * sizeof(glm::vec3) +
                                   c.adjacency.edges.size() * sizeof(Edge));
}

// What the prepared version streams, in bytes: six floats per face, two faces per edge.
std::int64_t preparedBytesRead(const SilhouetteCaster& c) {
  return static_cast<std::int64_t>(6 * c.faceCount() * sizeof(float) +
                                   c.edgeFaces.size() * sizeof(SilhouetteCaster::EdgeFaces));
}

const glm::vec4 light(3.0f, 4.0f, 5.0f, 1.0f);

// The light's distance, for the dual-space table: the shapes have radius 1 (the torus 1.3) about
// the origin. Near: 2.1 away, where the facing flags change fast across the surface; far: 71
// away; directional: towards (3, 4, 5) from infinitely far.
struct LightCase {
  const char* name;
  glm::vec4 position;
};
constexpr LightCase lightCases[] = {{"near", {0.9f, 1.2f, 1.5f, 1.0f}},
                                    {"far", {30.0f, 40.0f, 50.0f, 1.0f}},
                                    {"directional", {3.0f, 4.0f, 5.0f, 0.0f}}};

// The light's motion relative to the caster, for the near light: still (the same light in the
// caster's space every call, so DualSilhouettes::query reuses its last answer), or turned about
// the y axis by a fixed angle before every call (every call queries again).
struct Motion {
  const char* name;
  float degreesPerCall;  // 0: still
};
constexpr Motion motions[] = {{"still", 0.0f}, {"turn0.1", 0.1f}, {"turn10", 10.0f}};

// The near light after `step` calls turning it by `degrees` about the y axis.
glm::vec4 turnedLight(std::size_t step, float degrees) {
  const float a = glm::radians(std::fmod(degrees * static_cast<float>(step), 360.0f));
  const glm::vec4 p = lightCases[0].position;
  return {p.x * std::cos(a) + p.z * std::sin(a), p.y, -p.x * std::sin(a) + p.z * std::cos(a), 1.0f};
}

void meshVersion(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  std::size_t edges = 0;
  for (auto _ : state) {
    const std::vector<bool> lit = facesLight(c.mesh, light);
    const std::vector<SilhouetteEdge> silhouette = possibleSilhouetteEdges(c.adjacency, lit);
    edges = silhouette.size();
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
  state.counters["silhouette_edges"] = static_cast<double>(edges);
}

void prepared(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  for (auto _ : state) {
    facesLight(c, light, lit);
    possibleSilhouetteEdges(c, lit, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.faceCount()));
  state.SetBytesProcessed(state.iterations() * preparedBytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = static_cast<double>(silhouette.size());
}

void facing(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  for (auto _ : state) {
    facesLight(c, light, lit);
    benchmark::DoNotOptimize(lit.data());
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void edgepass(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  facesLight(c, light, lit);
  for (auto _ : state) {
    possibleSilhouetteEdges(c, lit, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void prepare(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    SilhouetteCaster s = prepareSilhouettes(c.mesh, c.adjacency);
    benchmark::DoNotOptimize(s.nx.data());
  }
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

// The brute force of part 1 (a SilhouetteCaster's two passes) and the dual-space query for one
// light: lightCases[which] held still, each dual call a fresh descent of the tree (as if the light
// had moved by a hair: the cost of one query); or, for which >= 3, the near light moving as
// motions[which - 3] says, each dual call through DualSilhouettes::query and its cache.
template <bool Dual>
void byLight(benchmark::State& state, const std::string& shape, const Size& size, std::size_t which) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  const DualSilhouettes* tree = Dual ? &dualTree(shape, size) : nullptr;
  const bool moving = which >= std::size(lightCases);
  const float degrees = moving ? motions[which - std::size(lightCases)].degreesPerCall : 0.0f;
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  std::size_t step = 0, edges = 0, calls = 0, tested = 0;
  for (auto _ : state) {
    const glm::vec4 l = moving ? turnedLight(step++, degrees) : lightCases[which].position;
    if constexpr (Dual) {
      if (moving)
        tree->query(l, silhouette);
      else
        tree->descend(l, silhouette);
    } else {
      facesLight(c, l, lit);
      possibleSilhouetteEdges(c, lit, silhouette);
    }
    benchmark::DoNotOptimize(silhouette.data());
    edges += silhouette.size();
    if constexpr (Dual) tested += tree->lastQuery().edgesTested;
    ++calls;
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = calls ? static_cast<double>(edges) / static_cast<double>(calls) : 0.0;
  if constexpr (Dual)
    state.counters["edges_tested"] = calls ? static_cast<double>(tested) / static_cast<double>(calls) : 0.0;
}

void dualPrepare(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  for (auto _ : state) {
    DualSilhouettes tree(c);
    benchmark::DoNotOptimize(&tree);
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

void scanPrepared(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  for (auto _ : state) {
    std::uint32_t sum = sumWords(c.nx) + sumWords(c.ny) + sumWords(c.nz) + sumWords(c.ax) + sumWords(c.ay) +
                        sumWords(c.az) + sumWords(c.edgeFaces);
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(state.iterations() * preparedBytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

// The prepared extraction and the scan of its arrays timed in alternating batches within one
// benchmark, each batch about 20 microseconds: both see the same load on a shared machine, and
// at 1k triangles (a call of about 2 microseconds, the arrays in L1) no timer's resolution or
// start-up enters. Counters: the median over batches of each one's time per call, the median of
// the batches' ratios, and the ratio of the fastest batches (the machine at its quietest).
void paired(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  const std::size_t batch = std::max<std::size_t>(1, 10000 / c.faceCount());
  std::vector<double> extraction, scanned, ratio;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const Clock::time_point t0 = Clock::now();
    for (std::size_t i = 0; i < batch; ++i) {
      facesLight(c, light, lit);
      possibleSilhouetteEdges(c, lit, silhouette);
      benchmark::DoNotOptimize(silhouette.data());
    }
    const Clock::time_point t1 = Clock::now();
    for (std::size_t i = 0; i < batch; ++i) {
      std::uint32_t sum = sumWords(c.nx) + sumWords(c.ny) + sumWords(c.nz) + sumWords(c.ax) + sumWords(c.ay) +
                          sumWords(c.az) + sumWords(c.edgeFaces);
      benchmark::DoNotOptimize(sum);
    }
    const Clock::time_point t2 = Clock::now();
    const double a = std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(batch),
                 b = std::chrono::duration<double, std::nano>(t2 - t1).count() / static_cast<double>(batch);
    extraction.push_back(a);
    scanned.push_back(b);
    ratio.push_back(a / b);
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  const auto least = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
  };
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = static_cast<double>(silhouette.size());
  state.counters["extraction_ns"] = median(extraction);
  state.counters["scan_ns"] = median(scanned);
  state.counters["ratio"] = median(ratio);
  state.counters["ratio_quietest"] = least(scanned) > 0.0 ? least(extraction) / least(scanned) : 0.0;
}

void faces(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    std::vector<bool> lit = facesLight(c.mesh, light);  // not const: DoNotOptimize takes a mutable lvalue
    benchmark::DoNotOptimize(lit);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

void edges(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  const std::vector<bool> lit = facesLight(c.mesh, light);
  for (auto _ : state) {
    const std::vector<SilhouetteEdge> silhouette = possibleSilhouetteEdges(c.adjacency, lit);
    benchmark::DoNotOptimize(silhouette.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

void scan(benchmark::State& state, const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  for (auto _ : state) {
    std::uint32_t sum = sumWords(c.mesh.indices) + sumWords(c.mesh.positions) + sumWords(c.adjacency.edges);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.mesh.triangleCount()));
  state.SetBytesProcessed(state.iterations() * bytesRead(c));
  state.counters["triangles"] = static_cast<double>(c.mesh.triangleCount());
}

// A silhouette of a closed mesh is made of closed loops: every vertex starts as many of its
// directed edges as it ends.
bool closedLoops(const PreparedCaster& c) {
  const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(c.adjacency, facesLight(c.mesh, light));
  std::vector<int> balance(c.mesh.positions.size(), 0);
  for (const SilhouetteEdge& e : edges) {
    ++balance[e.v0];
    --balance[e.v1];
  }
  for (int b : balance)
    if (b != 0) return false;
  return !edges.empty();
}

// The prepared version gives the mesh version's edges, in the same order and direction.
bool sameAsMeshVersion(const std::string& shape, const Size& size) {
  const PreparedCaster& c = caster(shape, size);
  const std::vector<SilhouetteEdge> a = possibleSilhouetteEdges(c.adjacency, facesLight(c.mesh, light)),
                                    b = possibleSilhouetteEdges(silhouetteCaster(shape, size), light);
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].v0 != b[i].v0 || a[i].v1 != b[i].v1) return false;
  return true;
}

// The dual-space query gives the prepared passes' edges for every light of the table, and for the
// first steps of the stepped light.
bool dualAsPrepared(const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  std::vector<SilhouetteEdge> found;
  auto same = [&](const glm::vec4& l) {
    dualTree(shape, size).query(l, found);
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(c, l);
    if (found.size() != expected.size() || expected.empty()) return false;
    for (std::size_t i = 0; i < found.size(); ++i)
      if (found[i].v0 != expected[i].v0 || found[i].v1 != expected[i].v1) return false;
    return true;
  };
  for (const LightCase& l : lightCases)
    if (!same(l.position)) return false;
  for (const Motion& m : motions)
    for (std::size_t step = 0; step < 10; ++step)
      if (!same(turnedLight(step, m.degreesPerCall))) return false;
  return true;
}

// Google Benchmark 1.8 replaced Run::error_occurred with Run::skipped; both are in use (Debian 12
// has 1.7, Debian 13 has 1.9).
template <typename R>
bool failed(const R& run) {
  if constexpr (requires { run.skipped; })
    return static_cast<int>(run.skipped) != 0;
  else
    return run.error_occurred;
}

// Keeps each run's time per iteration for the table: the median of its repetitions, which with
// --benchmark_enable_random_interleaving ran interleaved with the other benchmarks', so that a
// busy moment on a shared machine falls on all of them alike.
double medianOf(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

class TableReporter : public benchmark::ConsoleReporter {
 public:
  struct Row {
    double triangles = 0, edges = 0, tested = 0;
    std::vector<double> ns;                               // one per repetition
    std::map<std::string, std::vector<double>> counters;  // the paired benchmark's, per repetition
    double median() const { return medianOf(ns); }
    double counter(const std::string& name) const {
      const auto c = counters.find(name);
      return c == counters.end() ? 0.0 : medianOf(c->second);
    }
  };
  std::map<std::string, Row> rows;  // by name: "prepared/sphere/1k"

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (failed(run) || run.run_type != Run::RT_Iteration) continue;
      Row& row = rows[run.run_name.function_name];
      row.ns.push_back(run.GetAdjustedCPUTime());  // nanoseconds; CPU time, as the machine may be shared
      row.triangles = run.counters.at("triangles").value;
      if (run.counters.count("silhouette_edges")) row.edges = run.counters.at("silhouette_edges").value;
      if (run.counters.count("edges_tested")) row.tested = run.counters.at("edges_tested").value;
      for (const char* name : {"extraction_ns", "scan_ns", "ratio", "ratio_quietest"})
        if (run.counters.count(name)) row.counters[name].push_back(run.counters.at(name).value);
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

double perTriangle(const TableReporter& reporter, const std::string& name) {
  const auto row = reporter.rows.find(name);
  return row == reporter.rows.end() ? 0.0 : row->second.median() / row->second.triangles;
}

// The machine's load while the benchmark ran: the 1-minute load average at its start and end.
std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0.0;
  return in >> one ? std::to_string(one).substr(0, 4) : std::string("unknown");
}

void writeDualTable(const TableReporter& reporter, std::ofstream& out);

void writeTable(const TableReporter& reporter, const std::string& file, const std::string& loadBefore,
                const std::string& loadAfter, int repetitions) {
  std::ofstream out(file);
  char text[2048];
  std::snprintf(
      text, sizeof text,
      "# Silhouette extraction against a memory scan\n\n"
      "The possible silhouette edges of welded spheres and tori for a point light at (3, 4, 5), two\n"
      "ways (common/geometry/shadow_volume.h): **mesh**, `facesLight` + `possibleSilhouetteEdges` on the "
      "mesh and\n"
      "its adjacency (a gathered cross product per triangle, bit flags); **prepared** (the brute force),\n"
      "the same two passes on a `SilhouetteCaster` (face normals and first corners precomputed once and\n"
      "streamed, each edge's two faces read once against one-byte flags; identical edges). Each against\n"
      "a scan that sums the arrays it reads as 32-bit words: **scan** the indices, positions and edges\n"
      "(mesh), **scan-prepared** the six per-face floats and the edges' face pairs (prepared). Single\n"
      "thread, CPU time per call, the median of %d repetitions interleaved at random, all in one\n"
      "benchmark run; GB/s counts those arrays' bytes once per call. **paired**: the prepared passes\n"
      "and scan-prepared timed in alternating batches of about 20 us inside one benchmark (wall\n"
      "time), so that both see the same moment of a shared machine: the median of the batches'\n"
      "ratios, and the ratio of the two fastest batches (the machine at its quietest). The halves:\n"
      "facesLight / the facing pass, possibleSilhouetteEdges / the edge pass, each timed alone (its\n"
      "own benchmark, at its own moment of the shared machine), so they need not add up to the whole.\n"
      "prepare: building the\n"
      "SilhouetteCaster, once per caster. Load average (1 minute) of this 2-core machine, shared with\n"
      "other work: %s at the start, %s at the end. Written by `cmake --build build --target\n"
      "silhouette-benchmark` (every repetition's time in silhouette-extraction.csv, the plot in\n"
      "silhouette-extraction.svg).\n\n",
      repetitions, loadBefore.c_str(), loadAfter.c_str());
  out << text
      << "| shape | triangles | silhouette edges | mesh ns/tri | (facesLight + possibleSilhouetteEdges) | "
         "scan "
         "ns/tri | "
         "mesh / scan | prepared ns/tri | (facing + edge pass) | prepared GB/s | scan-prepared ns/tri | "
         "scan-prepared GB/s | prepared / scan-prepared | **paired: prepared / scan-prepared** | "
         "paired, quietest | prepare ns/tri (once) |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  double worst = 0.0, worstQuiet = 0.0;
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      const auto p = reporter.rows.find("prepared" + key);
      const auto pair = reporter.rows.find("paired" + key);
      if (p == reporter.rows.end() || reporter.rows.find("scan-prepared" + key) == reporter.rows.end() ||
          reporter.rows.find("mesh" + key) == reporter.rows.end() || pair == reporter.rows.end())
        continue;
      const double mesh = perTriangle(reporter, "mesh" + key), scan = perTriangle(reporter, "scan" + key),
                   prep = perTriangle(reporter, "prepared" + key),
                   scanPrep = perTriangle(reporter, "scan-prepared" + key);
      const double ratio = pair->second.counter("ratio"), quiet = pair->second.counter("ratio_quietest");
      worst = std::max(worst, ratio);
      worstQuiet = std::max(worstQuiet, quiet);
      const double bytes = static_cast<double>(preparedBytesRead(silhouetteCaster(shape, size)));
      char line[512];
      std::snprintf(
          line, sizeof line,
          "| %s | %.0f | %.0f | %.2f | %.2f + %.2f | %.2f | %.1f | %.2f | %.2f + %.2f | %.1f | %.2f | "
          "%.1f | %.2f | **%.2f** | %.2f | %.1f |\n",
          shape, p->second.triangles, p->second.edges, mesh, perTriangle(reporter, "faces" + key),
          perTriangle(reporter, "edges" + key), scan, mesh / scan, prep,
          perTriangle(reporter, "facing" + key), perTriangle(reporter, "edgepass" + key),
          bytes / (prep * p->second.triangles), scanPrep, bytes / (scanPrep * p->second.triangles),
          prep / scanPrep, ratio, quiet, perTriangle(reporter, "prepare" + key));
      out << line;
    }
  std::snprintf(text, sizeof text,
                "\nThe brute force is within %.2f times the scan of the arrays it reads at every size "
                "(paired medians), %.2f at the quietest.\n",
                worst, worstQuiet);
  out << text;
  writeDualTable(reporter, out);
}

// The second table: the dual-space query beside part 1's brute force by the light's distance and
// motion, and where each wins, from the numbers in it.
void writeDualTable(const TableReporter& reporter, std::ofstream& out) {
  out << "\n## Dual space against the brute force, by the light's distance and motion\n\n"
      << "The possible silhouette edges two ways, identical edges (checked by `--quick`): **brute force**,\n"
      << "the two passes of part 1 on a `SilhouetteCaster` (every face's facing test, every edge's two\n"
      << "flags); **dual**, `DualSilhouettes` (common/geometry/dual_silhouette.h), the 4D tree of face\n"
      << "planes descended only where the light's plane crosses a cell, each edge reached tested exactly.\n"
      << "Distance, the light held still and the tree descended on every call (`descend`, the cost of one\n"
      << "query): near (0.9, 1.2, 1.5), 2.1 from the centre of shapes of radius 1 (torus 1.3); far\n"
      << "(30, 40, 50), 71 away; directional towards (3, 4, 5). Motion, the near light through `query`,\n"
      << "which descends only when the light moved relative to the caster: still (the same light in the\n"
      << "caster's space every call: the last answer reused), turn0.1 and turn10 (turned 0.1 or 10\n"
      << "degrees about y before every call: a descent every call). The brute force has no cache: it\n"
      << "does all its work on every call. CPU time per call, median of the repetitions; the tree's\n"
      << "build (dual prepare) is paid once per caster, apart. Edges tested: those the query decided\n"
      << "exactly, per call (the brute force tests every edge).\n\n"
      << "| shape | triangles | light | silhouette edges | brute force ns/tri | dual ns/tri | **dual / brute "
         "force** | dual edges tested | dual prepare ns/tri (once) |\n"
      << "|---|---:|---|---:|---:|---:|---:|---:|---:|\n";
  std::map<std::string, std::vector<std::string>> dualWins, bruteWins;  // by light: "sphere 1k"
  std::vector<std::string> order;
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      std::vector<std::string> wheres;
      for (const LightCase& l : lightCases) wheres.push_back(l.name);
      for (const Motion& m : motions) wheres.push_back(m.name);
      for (const std::string& where : wheres) {
        // The brute force has no cache: a still light costs it what the near light does.
        const auto b = reporter.rows.find("prepared-" + (where == "still" ? std::string("near") : where) +
                                          key),
                   d = reporter.rows.find("dual-" + where + key);
        if (b == reporter.rows.end() || d == reporter.rows.end()) continue;
        const double brute = perTriangle(reporter, b->first), dual = perTriangle(reporter, d->first);
        if (std::find(order.begin(), order.end(), where) == order.end()) order.push_back(where);
        (dual < brute ? dualWins : bruteWins)[where].push_back(std::string(shape) + " " + size.name);
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %.0f | %s | %.0f | %.2f | %.2f | **%.2f** | %.0f | %.1f |\n",
                      shape, b->second.triangles, where.c_str(), d->second.edges, brute, dual, dual / brute,
                      d->second.tested, perTriangle(reporter, "dual-prepare" + key));
        out << line;
      }
    }
  out << "\nWhere each wins, by light (the faster per call in the table above):\n\n";
  const auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
    return s;
  };
  for (const std::string& where : order)
    if (dualWins[where].empty())
      out << "- " << where << ": the brute force, at every size of both shapes.\n";
    else if (bruteWins[where].empty())
      out << "- " << where << ": dual space, at every size of both shapes.\n";
    else
      out << "- " << where << ": dual space at " << list(dualWins[where]) << "; the brute force at "
          << list(bruteWins[where]) << ".\n";
  // A still light pays the tree's build back after build / (brute force - reused answer) calls.
  double fewest = 1e300, most = 0.0;
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      if (!reporter.rows.count("prepared-near" + key) || !reporter.rows.count("dual-still" + key) ||
          !reporter.rows.count("dual-prepare" + key))
        continue;
      const double saved =
          perTriangle(reporter, "prepared-near" + key) - perTriangle(reporter, "dual-still" + key);
      if (saved <= 0.0) continue;
      const double calls = perTriangle(reporter, "dual-prepare" + key) / saved;
      fewest = std::min(fewest, calls);
      most = std::max(most, calls);
    }
  if (most > 0.0) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "\nA still light is the one case dual space wins: it answers from the last query. It pays\n"
                  "the tree's build back after %.0f to %.0f still calls.\n",
                  fewest, most);
    out << line;
  }
}

void writeRaw(const TableReporter& reporter, const std::string& file) {
  std::ofstream out(file);
  out << "benchmark,triangles,silhouette_edges,median_cpu_ns,repetition_cpu_ns\n";
  for (const auto& [name, row] : reporter.rows) {
    out << name << "," << row.triangles << "," << row.edges << "," << row.median() << ",";
    for (std::size_t i = 0; i < row.ns.size(); ++i) out << (i ? " " : "") << row.ns[i];
    out << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string table, raw;
  int repetitions = 1;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick")
      quick = true;
    else if (arg == "--table" && i + 1 < argc)
      table = argv[++i];
    else if (arg == "--raw" && i + 1 < argc)
      raw = argv[++i];
    else {
      if (arg.rfind("--benchmark_repetitions=", 0) == 0) repetitions = std::atoi(arg.c_str() + 24);
      rest.push_back(argv[i]);
    }
  }
  int restCount = static_cast<int>(rest.size());
  benchmark::Initialize(&restCount, rest.data());
  if (benchmark::ReportUnrecognizedArguments(restCount, rest.data())) return 2;

  const std::size_t count = quick ? 3 : std::size(sizes);
  for (const char* shape : {"sphere", "torus"})
    for (std::size_t i = 0; i < count; ++i) {
      const Size& size = sizes[i];
      const std::string key = std::string("/") + shape + "/" + size.name;
      const std::pair<const char*, void (*)(benchmark::State&, const std::string&, const Size&)> runs[] = {
          {"mesh", meshVersion},
          {"prepared", prepared},
          {"scan", scan},
          {"scan-prepared", scanPrepared},
          {"paired", paired},
          {"faces", faces},
          {"edges", edges},
          {"facing", facing},
          {"edgepass", edgepass},
          {"prepare", prepare},
          {"dual-prepare", dualPrepare}};
      for (const auto& [name, run] : runs)
        benchmark::RegisterBenchmark((name + key).c_str(), run, std::string(shape), size);
      for (std::size_t k = 0; k < std::size(lightCases) + std::size(motions); ++k) {
        const std::string where =
            k < std::size(lightCases) ? lightCases[k].name : motions[k - std::size(lightCases)].name;
        const std::string s = shape;
        if (where != "still")  // the brute force has no cache: still costs what near does
          benchmark::RegisterBenchmark(
              ("prepared-" + where + key).c_str(),
              [s, &size, k](benchmark::State& st) { byLight<false>(st, s, size, k); });
        benchmark::RegisterBenchmark(("dual-" + where + key).c_str(),
                                     [s, &size, k](benchmark::State& st) { byLight<true>(st, s, size, k); });
      }
      if (quick && !dualAsPrepared(shape, size)) {
        std::cerr << shape << " " << size.name
                  << ": the dual-space silhouette differs from the prepared one\n";
        return 1;
      }
      if (quick && !closedLoops(caster(shape, size))) {
        std::cerr << shape << " " << size.name << ": the silhouette is not a set of closed loops\n";
        return 1;
      }
      if (quick && !sameAsMeshVersion(shape, size)) {
        std::cerr << shape << " " << size.name
                  << ": the prepared silhouette differs from the mesh version's\n";
        return 1;
      }
    }
  const std::string loadBefore = loadAverage();
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!table.empty()) writeTable(reporter, table, loadBefore, loadAverage(), repetitions);
  if (!raw.empty()) writeRaw(reporter, raw);
  benchmark::Shutdown();
  return 0;
}
