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
// prepare: building the SilhouetteCaster, once per caster. Then the brute force beside the two
// dual-space structures of dual_silhouette.h, Wallner's hextree (DualSilhouettes, dual-*) and the
// hierarchy over the dual edges (DualEdgeBvh, bvh-*), by the light's distance and motion, their
// builds (dual-prepare, bvh-prepare), and the three for a moving light in alternating batches
// (paired-turn0.1).
//
//   silhouette_benchmark [--quick] [--table FILE.md] [--raw FILE.csv] [benchmark flags]
//
// Before anything is timed, at every size it runs: both dual-space structures give the prepared
// version's edges, order and direction, for every light of the tables; exit 1 if not. --quick:
// the three smallest sizes only, and two more checks: every silhouette is a set of closed loops
// (each vertex leaves it as often as it enters it), and the prepared version gives the mesh
// version's edges; exit 1 if not. --table writes the results as Markdown tables (triangles, ns
// per triangle, GB/s, ratios to the scans and to the brute force); --raw the CPU time of every
// repetition of every benchmark as CSV.
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

const DualEdgeBvh& dualBvh(const std::string& shape, const Size& size) {
  static std::map<std::string, std::unique_ptr<DualEdgeBvh>> cache;
  auto& slot = cache[shape + size.name];
  if (!slot) slot = std::make_unique<DualEdgeBvh>(silhouetteCaster(shape, size));
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

// The three ways to the same edges: part 1's brute force (a SilhouetteCaster's two passes),
// Wallner's hextree (DualSilhouettes) and the hierarchy over the dual edges (DualEdgeBvh).
enum class Method { Brute, Hextree, Bvh };

// A caster's three structures, looked up once, outside the timed loops.
struct Structures {
  const SilhouetteCaster& caster;
  const DualSilhouettes& hextree;
  const DualEdgeBvh& bvh;
};
Structures structures(const std::string& shape, const Size& size) {
  return {silhouetteCaster(shape, size), dualTree(shape, size), dualBvh(shape, size)};
}

// One call of `method` for the light `towards`: through the dual structures' query() (and its
// cache) when `cached`, else a fresh descent. Returns the edges the call tested (brute force: 0).
std::size_t extract(Method method, const Structures& s, const glm::vec4& towards, bool cached,
                    std::vector<std::uint8_t>& lit, std::vector<SilhouetteEdge>& silhouette) {
  switch (method) {
    case Method::Brute:
      facesLight(s.caster, towards, lit);
      possibleSilhouetteEdges(s.caster, lit, silhouette);
      return 0;
    case Method::Hextree:
      cached ? s.hextree.query(towards, silhouette) : s.hextree.descend(towards, silhouette);
      return s.hextree.lastQuery().edgesTested;
    case Method::Bvh:
      cached ? s.bvh.query(towards, silhouette) : s.bvh.descend(towards, silhouette);
      return s.bvh.lastQuery().edgesTested;
  }
  return 0;
}

// One method for one light: lightCases[which] held still, each dual call a fresh descent (as if
// the light had moved by a hair: the cost of one query); or, for which >= 3, the near light moving
// as motions[which - 3] says, each dual call through query() and its cache.
void byLight(benchmark::State& state, Method method, const std::string& shape, const Size& size,
             std::size_t which) {
  const Structures all = structures(shape, size);  // built before the clock starts
  const SilhouetteCaster& c = all.caster;
  const bool moving = which >= std::size(lightCases);
  const float degrees = moving ? motions[which - std::size(lightCases)].degreesPerCall : 0.0f;
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  std::size_t step = 0, edges = 0, calls = 0, tested = 0;
  for (auto _ : state) {
    const glm::vec4 l = moving ? turnedLight(step++, degrees) : lightCases[which].position;
    tested += extract(method, all, l, moving, lit, silhouette);
    benchmark::DoNotOptimize(silhouette.data());
    edges += silhouette.size();
    ++calls;
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["silhouette_edges"] = calls ? static_cast<double>(edges) / static_cast<double>(calls) : 0.0;
  if (method != Method::Brute)
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

void bvhPrepare(benchmark::State& state, const std::string& shape, const Size& size) {
  const SilhouetteCaster& c = silhouetteCaster(shape, size);
  for (auto _ : state) {
    DualEdgeBvh bvh(c);
    benchmark::DoNotOptimize(&bvh);
  }
  state.counters["triangles"] = static_cast<double>(c.faceCount());
}

// The three methods for the near light turning 0.1 degree before every call, timed in alternating
// batches within one benchmark (each batch about 20 microseconds of the brute force, each method
// stepping through the same lights), so that all three see the same moment of the shared machine.
// Counters: the median over rounds of each dual method's time over the brute force's.
void pairedMoving(benchmark::State& state, const std::string& shape, const Size& size) {
  const Structures all = structures(shape, size);
  const SilhouetteCaster& c = all.caster;
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> silhouette;
  const std::size_t batch = std::max<std::size_t>(1, 10000 / c.faceCount());
  const float degrees = motions[1].degreesPerCall;
  std::size_t steps[3] = {0, 0, 0};
  std::vector<double> hextree, bvh;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    double ns[3];
    for (Method m : {Method::Brute, Method::Hextree, Method::Bvh}) {
      std::size_t& step = steps[static_cast<int>(m)];
      const Clock::time_point t0 = Clock::now();
      for (std::size_t i = 0; i < batch; ++i) {
        extract(m, all, turnedLight(step++, degrees), true, lit, silhouette);
        benchmark::DoNotOptimize(silhouette.data());
      }
      ns[static_cast<int>(m)] = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
    }
    hextree.push_back(ns[1] / ns[0]);
    bvh.push_back(ns[2] / ns[0]);
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  state.counters["triangles"] = static_cast<double>(c.faceCount());
  state.counters["hextree_ratio"] = median(hextree);
  state.counters["bvh_ratio"] = median(bvh);
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

// Both dual-space structures give the prepared passes' edges, in the same order and direction,
// for every light of the table and the first steps of every moving light, through query() and
// through a fresh descent.
bool dualAsPrepared(const std::string& shape, const Size& size) {
  const Structures all = structures(shape, size);
  const SilhouetteCaster& c = all.caster;
  std::vector<SilhouetteEdge> found;
  std::vector<std::uint8_t> lit;
  auto same = [&](const glm::vec4& l) {
    const std::vector<SilhouetteEdge> expected = possibleSilhouetteEdges(c, l);
    if (expected.empty()) return false;
    for (Method m : {Method::Hextree, Method::Bvh})
      for (bool cached : {true, false}) {
        extract(m, all, l, cached, lit, found);
        if (found.size() != expected.size()) return false;
        for (std::size_t i = 0; i < found.size(); ++i)
          if (found[i].v0 != expected[i].v0 || found[i].v1 != expected[i].v1) return false;
      }
    return true;
  };
  for (const LightCase& l : lightCases)
    if (!same(l.position)) return false;
  for (const Motion& m : motions)
    for (std::size_t step = 0; step < 20; ++step)
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
      for (const char* name : {"extraction_ns", "scan_ns", "ratio", "ratio_quietest", "hextree_ratio", "bvh_ratio"})
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

// The second table: both dual-space methods beside part 1's brute force by the light's distance
// and motion; the third: their builds and the moving light timed in alternating batches; then
// where each wins, from the numbers in them.
void writeDualTable(const TableReporter& reporter, std::ofstream& out) {
  out << "\n## Dual space against the brute force, by the light's distance and motion\n\n"
      << "The possible silhouette edges three ways, identical edges (checked before timing, at every size\n"
      << "of this run, for every light below and the first 20 steps of each moving light, through the\n"
      << "cache and by fresh descents): **brute force**, the two passes of part 1 on a `SilhouetteCaster`\n"
      << "(every face's facing test, every edge's two flags); **hextree**, `DualSilhouettes`, Wallner's 4D\n"
      << "tree of face planes (16 children a cell, split at the centre; a segment that crosses a split\n"
      << "stays in that cell), descended only where the light's plane crosses a cell; **BVH**,\n"
      << "`DualEdgeBvh`, a hierarchy of boxes fitted to the dual edges (both faces' unit planes; four\n"
      << "children a node tested at once, median splits, leaves of at most 8 edges stored with their\n"
      << "planes in tree order; after Sander et al.'s search tree of edge clusters), both in\n"
      << "common/geometry/dual_silhouette.h. Distance, the light held still and each dual call a fresh\n"
      << "descent (`descend`, the cost of one query): near (0.9, 1.2, 1.5), 2.1 from the centre of shapes\n"
      << "of radius 1 (torus 1.3); far (30, 40, 50), 71 away; directional towards (3, 4, 5). Motion, the\n"
      << "near light through `query`, which descends only when the light moved relative to the caster:\n"
      << "still (the same light in the caster's space every call: the last answer reused), turn0.1 and\n"
      << "turn10 (turned 0.1 or 10 degrees about y before every call: a descent every call). The brute\n"
      << "force has no cache: it does all its work on every call. CPU time per call, median of the\n"
      << "repetitions; the builds are paid once per caster, apart (next table). Edges tested: those whose\n"
      << "faces' planes the query tested, per call (the brute force tests every edge).\n\n"
      << "| shape | triangles | light | silhouette edges | brute force ns/tri | hextree ns/tri | hextree / "
         "brute force | BVH ns/tri | **BVH / brute force** | hextree edges tested | BVH edges tested |\n"
      << "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  // Which methods beat the brute force where, by light: "sphere 1k".
  std::map<std::string, std::vector<std::string>> hextreeWins, hextreeLoses, bvhWins, bvhLoses;
  std::vector<std::string> order;
  const auto row = [&](const std::string& name) { return reporter.rows.find(name); };
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name, label = std::string(shape) + " " + size.name;
      std::vector<std::string> wheres;
      for (const LightCase& l : lightCases) wheres.push_back(l.name);
      for (const Motion& m : motions) wheres.push_back(m.name);
      for (const std::string& where : wheres) {
        // The brute force has no cache: a still light costs it what the near light does.
        const auto b = row("prepared-" + (where == "still" ? std::string("near") : where) + key),
                   d = row("dual-" + where + key), v = row("bvh-" + where + key);
        if (b == reporter.rows.end() || d == reporter.rows.end() || v == reporter.rows.end()) continue;
        const double brute = perTriangle(reporter, b->first), hextree = perTriangle(reporter, d->first),
                     bvh = perTriangle(reporter, v->first);
        if (std::find(order.begin(), order.end(), where) == order.end()) order.push_back(where);
        (hextree < brute ? hextreeWins : hextreeLoses)[where].push_back(label);
        (bvh < brute ? bvhWins : bvhLoses)[where].push_back(label);
        char line[512];
        std::snprintf(line, sizeof line,
                      "| %s | %.0f | %s | %.0f | %.2f | %.2f | %.2f | %.3f | **%.3f** | %.0f | %.0f |\n", shape,
                      b->second.triangles, where.c_str(), v->second.edges, brute, hextree, hextree / brute, bvh,
                      bvh / brute, d->second.tested, v->second.tested);
        out << line;
      }
    }

  out << "\n## Builds, and the moving light in alternating batches\n\n"
      << "Each dual structure is built once per caster (CPU ns per triangle, median of the repetitions).\n"
      << "A moving light (turn0.1) pays the BVH's build back after build / (brute force - BVH) calls,\n"
      << "from the table above. **paired**: the three methods for the near light turning 0.1 degree a\n"
      << "call, timed in alternating batches of about 20 us of the brute force inside one benchmark (wall\n"
      << "time, each method through the same lights), so that all three see the same moment of the\n"
      << "shared machine: the median of the rounds' ratios to the brute force.\n\n"
      << "| shape | triangles | hextree build ns/tri | BVH build ns/tri | BVH build repaid after (turn0.1 "
         "calls) | paired turn0.1: hextree / brute force | **paired turn0.1: BVH / brute force** |\n"
      << "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const char* shape : {"sphere", "torus"})
    for (const Size& size : sizes) {
      const std::string key = std::string("/") + shape + "/" + size.name;
      const auto pair = row("paired-turn0.1" + key), b = row("prepared-turn0.1" + key), v = row("bvh-turn0.1" + key);
      if (pair == reporter.rows.end() || b == reporter.rows.end() || v == reporter.rows.end()) continue;
      const double saved = perTriangle(reporter, b->first) - perTriangle(reporter, v->first),
                   build = perTriangle(reporter, "bvh-prepare" + key);
      char repaid[32] = "never";
      if (saved > 0.0) std::snprintf(repaid, sizeof repaid, "%.0f", std::ceil(build / saved));
      char line[512];
      std::snprintf(line, sizeof line, "| %s | %.0f | %.1f | %.1f | %s | %.2f | **%.3f** |\n", shape,
                    b->second.triangles, perTriangle(reporter, "dual-prepare" + key), build, repaid,
                    pair->second.counter("hextree_ratio"), pair->second.counter("bvh_ratio"));
      out << line;
    }

  out << "\nWhere each wins against the brute force, by light (the faster per call in the first table):\n\n";
  const auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
    return s;
  };
  const auto wins = [&](const std::vector<std::string>& w, const std::vector<std::string>& l) {
    if (w.empty()) return std::string("at no size");
    if (l.empty()) return std::string("at every size of both shapes");
    return "at " + list(w) + " (not at " + list(l) + ")";
  };
  for (const std::string& where : order)
    out << "- " << where << ": the BVH " << wins(bvhWins[where], bvhLoses[where]) << "; the hextree "
        << wins(hextreeWins[where], hextreeLoses[where]) << ".\n";
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
          {"dual-prepare", dualPrepare},
          {"bvh-prepare", bvhPrepare},
          {"paired-turn0.1", pairedMoving}};
      for (const auto& [name, run] : runs)
        benchmark::RegisterBenchmark((name + key).c_str(), run, std::string(shape), size);
      for (std::size_t k = 0; k < std::size(lightCases) + std::size(motions); ++k) {
        const std::string where =
            k < std::size(lightCases) ? lightCases[k].name : motions[k - std::size(lightCases)].name;
        const std::string s = shape;
        for (const auto& [prefix, way] : {std::pair{"prepared-", Method::Brute},
                                          std::pair{"dual-", Method::Hextree}, std::pair{"bvh-", Method::Bvh}}) {
          if (way == Method::Brute && where == "still") continue;  // no cache: still costs what near does
          const Method method = way;  // a lambda captures a variable, not a structured binding (clang 14)
          benchmark::RegisterBenchmark((prefix + where + key).c_str(), [s, &size, k, method](benchmark::State& st) {
            byLight(st, method, s, size, k);
          });
        }
      }
      if (!dualAsPrepared(shape, size)) {  // at every size, before anything is timed
        std::cerr << shape << " " << size.name
                  << ": a dual-space silhouette differs from the prepared one\n";
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
