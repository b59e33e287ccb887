#include "gl/options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "geometry/solar.h"
#include "gl/errors.h"
#include "gl/window_keys.h"

namespace stencil {
namespace {

// 0.5, 4: a constant as the help and lessons/run write it.
std::string shortNumber(float v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

template <typename T>
T parseNumber(const std::string& flag, const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec == std::errc::result_out_of_range && ptr == end)
    throw UsageError(flag + " " + text + " is out of range" +
                     (std::is_integral_v<T> ? " (" + std::to_string(std::numeric_limits<T>::min()) + ".." +
                                                  std::to_string(std::numeric_limits<T>::max()) + ")"
                                            : std::string()));
  if (ec != std::errc() || ptr != end)
    throw UsageError(flag + (std::is_integral_v<T> ? " expects an integer" : " expects a number") +
                     ", got '" + text + "'");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) throw UsageError(flag + " expects a finite number, got '" + text + "'");
  return value;
}

std::string optionRange(const Option& o) {
  return std::to_string(o.min) + ".." + std::to_string(o.max);
}

}  // namespace

const Variant& findVariant(const LessonInfo& info, const std::string& name) {
  if (name.empty()) return info.variants.front();
  for (const Variant& v : info.variants)
    if (v.name == name) return v;
  throw UsageError("unknown variant '" + name + "'; --list-variants shows them");
}

std::vector<std::pair<std::string, int>> settingsAwayFromVariant(const LessonInfo& info, const std::string& variant,
                                                                 const std::vector<Option>& options) {
  const std::vector<Option> variantValues = optionsFor(info, variant, {});
  std::vector<std::pair<std::string, int>> settings;
  for (std::size_t i = 0; i < options.size() && i < variantValues.size(); ++i)
    if (options[i].value != variantValues[i].value) settings.emplace_back(options[i].name, options[i].value);
  return settings;
}

std::vector<Option> optionsFor(const LessonInfo& info, const std::string& variant,
                               const std::vector<std::pair<std::string, int>>& settings) {
  std::vector<Option> options = info.options;
  for (const Option& o : options)
    if (o.value < o.min || o.value > o.max)
      throw std::logic_error("option '" + o.name + "' defaults to " + std::to_string(o.value) +
                             ", outside its range " + optionRange(o));
  auto apply = [&](const std::string& name, int value) {
    for (Option& o : options)
      if (o.name == name) {
        if (value < o.min || value > o.max)
          throw UsageError("option '" + name + "' takes " + optionRange(o) + ", got " +
                           std::to_string(value));
        o.value = value;
        return;
      }
    throw UsageError("unknown option '" + name + "'; --help lists the options");
  };
  for (const auto& [name, value] : findVariant(info, variant).settings) apply(name, value);
  for (const auto& [name, value] : settings) apply(name, value);
  return options;
}

CommandLine parseCommandLine(const LessonInfo& info, int argc, char** argv) {
  CommandLine cl;
  bool spanGiven = false, stepGiven = false;
  // A flag that names a file or a folder may be given once: with two, one file would silently not
  // be written (or read). Other flags may be given again, the last one counting (--size, --time).
  static const std::vector<std::string> paths = {"--out",    "--stencil-out", "--depth-out",    "--passes",
                                                 "--golden", "--artifacts",   "--shader-dir",   "--oracle",
                                                 "--scene",  "--mask-out",    "--shadow-hours"};
  std::vector<std::string> given;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (std::find(paths.begin(), paths.end(), flag) != paths.end()) {
      if (std::find(given.begin(), given.end(), flag) != given.end())
        throw UsageError(flag + " given twice; each file or folder flag names one");
      given.push_back(flag);
    }
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(flag + " needs a value; --help shows the flags");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h")
      cl.help = true;
    else if (flag == "--list-variants")
      cl.listVariants = true;
    else if (flag == "--headless")
      cl.headless = true;
    else if (flag == "--backend") {
      const std::string name = value();
      cl.backend = parseBackend(name);
      if (!cl.backend) throw UsageError("--backend takes osmesa, egl or window, got '" + name + "'");
    } else if (flag == "--size") {
      const std::string s = value();
      const auto x = s.find('x');
      if (x == std::string::npos || x == 0 || x + 1 == s.size() || s.find_first_not_of("0123456789", 0) != x ||
          s.find_first_not_of("0123456789", x + 1) != std::string::npos)
        throw UsageError("--size expects WxH, two whole numbers (e.g. 640x480), got '" + s + "'");
      cl.width = parseNumber<int>("--size", s.substr(0, x));
      cl.height = parseNumber<int>("--size", s.substr(x + 1));
      if (cl.width < 1 || cl.height < 1 || cl.width > 8192 || cl.height > 8192)
        throw UsageError("--size must be between 1x1 and 8192x8192, got '" + s + "'");
    } else if (flag == "--time") {
      const std::string t = value();
      cl.time = parseNumber<double>(flag, t);
      if (std::abs(cl.time) > kMaxTime)
        throw UsageError("--time must be within -1e6..1e6 seconds, got '" + t + "'");
    } else if (flag == "--frames") {
      const std::string n = value();
      const long long frames = parseNumber<long long>(flag, n);
      if (frames < 1 || frames > std::numeric_limits<int>::max())
        throw UsageError("--frames must be between 1 and " + std::to_string(std::numeric_limits<int>::max()) +
                         ", got '" + n + "'");
      cl.frames = static_cast<int>(frames);
    } else if (flag == "--variant") {
      cl.variant = value();
      if (cl.variant.empty()) throw UsageError("unknown variant ''; --list-variants shows them");
    } else if (flag == "--set") {
      const std::string s = value();
      const auto eq = s.find('=');
      if (eq == std::string::npos) throw UsageError("--set expects NAME=VALUE, got '" + s + "'");
      const std::string name = s.substr(0, eq);
      const auto option = std::find_if(info.options.begin(), info.options.end(),
                                       [&](const Option& o) { return o.name == name; });
      if (option == info.options.end()) throw UsageError("unknown option '" + name + "'; --help lists the options");
      // An integer past int's range is past the option's too: say the option's (the scene light's
      // range grows with a scene file, up to int's).
      const std::string text = s.substr(eq + 1);
      int parsed = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), parsed);
      if (ec == std::errc::result_out_of_range && ptr == text.data() + text.size() && name != info.sceneLightOption)
        throw UsageError("option '" + name + "' takes " + optionRange(*option) + ", got " + text);
      cl.settings.emplace_back(name, parseNumber<int>("--set " + name, text));
    } else if (flag == "--out")
      cl.out = value();
    else if (flag == "--stencil-out")
      cl.stencilOut = value();
    else if (flag == "--depth-out")
      cl.depthOut = value();
    else if (flag == "--stencil-view") {
      const std::string v = value();
      if (v != "ramp" && v != "bits") throw UsageError("--stencil-view takes ramp or bits, got '" + v + "'");
      cl.stencilBitPlanes = v == "bits";
    } else if (flag == "--passes")
      cl.passesDir = value();
    else if (flag == "--stats")
      cl.stats = true;
    else if (flag == "--stats-frames")
      cl.stats = cl.statsFrames = true;
    else if (flag == "--golden")
      cl.golden = value();
    else if (flag == "--oracle")
      cl.oracle = value();
    else if (flag == "--scene")
      cl.scene = value();
    else if (flag == "--mask-out")
      cl.maskOut = value();
    else if (flag == "--shadow-hours")
      cl.shadowHours = value();
    else if (flag == "--shadow-span") {
      const std::string span = value();
      const auto clock = [&](std::string_view hhmm) {
        const auto t = parseCivilTime("2000-01-01", hhmm);
        if (!t || !civilTimeProblem(*t).empty())
          throw UsageError("--shadow-span expects HH:MM-HH:MM within a day, got '" + span + "'");
        return t->hour * 60 + t->minute;
      };
      // H:MM or HH:MM at each end: "9:00-17:00" as the pages write it.
      const std::size_t dash = span.find('-');
      const auto end = [&](std::string part) {
        if (part.size() == 4) part = "0" + part;
        if (part.size() != 5)
          throw UsageError("--shadow-span expects HH:MM-HH:MM within a day, got '" + span + "'");
        return clock(part);
      };
      if (dash == std::string::npos)
        throw UsageError("--shadow-span expects HH:MM-HH:MM within a day, got '" + span + "'");
      cl.shadowFrom = end(span.substr(0, dash));
      cl.shadowTo = end(span.substr(dash + 1));
      if (cl.shadowTo < cl.shadowFrom)
        throw UsageError("--shadow-span ends before it starts: '" + span + "'");
      spanGiven = true;
    } else if (flag == "--shadow-step") {
      const std::string step = value();
      cl.shadowStep = parseNumber<int>(flag, step);
      if (cl.shadowStep < 1 || cl.shadowStep > 24 * 60)
        throw UsageError("--shadow-step must be 1 to 1440 minutes, got '" + step + "'");
      stepGiven = true;
    } else if (flag == "--update-golden")
      cl.updateGolden = true;
    else if (flag == "--artifacts")
      cl.artifacts = value();
    else if (flag == "--shader-dir")
      cl.shaderDir = value();
    else if (flag == "--stencil-bits") {
      cl.stencilBits = parseNumber<int>(flag, value());
      if (cl.stencilBits != 0 && cl.stencilBits != 8) throw UsageError("--stencil-bits takes 8 or 0");
    } else if (flag == "--ui-scale") {
      const std::string v = value();
      const float scale = parseNumber<float>(flag, v);
      if (scale < kMinUiScale || scale > kMaxUiScale)
        throw UsageError("--ui-scale must be between " + shortNumber(kMinUiScale) + " and " +
                         shortNumber(kMaxUiScale) + ", got '" + v + "'");
      cl.uiScale = scale;
    } else if (flag == "--position") {
      const std::string s = value();
      const auto comma = s.find(',');
      if (comma == std::string::npos || comma == 0 || comma + 1 == s.size() ||
          s.find_first_not_of("-0123456789", 0) != comma ||
          s.find_first_not_of("-0123456789", comma + 1) != std::string::npos)
        throw UsageError("--position expects X,Y, two whole numbers (e.g. 100,50), got '" + s + "'");
      const int x = parseNumber<int>(flag, s.substr(0, comma)), y = parseNumber<int>(flag, s.substr(comma + 1));
      if (std::abs(x) > 65536 || std::abs(y) > 65536)
        throw UsageError("--position must be within -65536..65536 each way, got '" + s + "'");
      cl.position = std::pair{x, y};
    } else if (flag == "--view") {
      const std::string v = value();
      const auto* it = std::find(std::begin(kViewNames), std::end(kViewNames), v);
      if (it == std::end(kViewNames))
        throw UsageError("--view takes colour, stencil, grey, bits or depth, got '" + v + "'");
      cl.view = static_cast<int>(it - std::begin(kViewNames));
    } else if (flag == "--panel") {
      const std::string v = value();
      if (v != "shown" && v != "hidden") throw UsageError("--panel takes shown or hidden, got '" + v + "'");
      cl.panelHidden = v == "hidden";
    } else if (flag == "--quiet" || flag == "-q")
      cl.quiet = true;
    else
      throw UsageError("unknown flag '" + flag + "'; --help shows the flags");
  }
  if ((spanGiven || stepGiven) && !cl.shadowHours)
    throw UsageError(std::string(spanGiven ? "--shadow-span" : "--shadow-step") +
                     " needs --shadow-hours FILE.png");
  if (cl.shadowHours && (cl.shadowTo - cl.shadowFrom) / cl.shadowStep + 1 > 255)
    throw UsageError("--shadow-span and --shadow-step make " +
                     std::to_string((cl.shadowTo - cl.shadowFrom) / cl.shadowStep + 1) +
                     " steps; at most 255 (the raw counts are one byte per pixel)");
  if (cl.shadowHours && cl.shadowTo > cl.shadowFrom && cl.shadowStep > cl.shadowTo - cl.shadowFrom)
    throw UsageError("--shadow-step " + std::to_string(cl.shadowStep) + " min is longer than the span's " +
                     std::to_string(cl.shadowTo - cl.shadowFrom) +
                     " min: its one step would count for more time than the span has");
  if (cl.shadowHours && cl.backend == Backend::Window)
    throw UsageError("--shadow-hours renders headless; it contradicts --backend window");
  if (cl.shadowHours && cl.frames)
    throw UsageError("--shadow-hours renders one frame per step; drop --frames");
  if (cl.shadowHours && cl.stats)
    throw UsageError("--shadow-hours writes its steps on stderr, no --stats JSON; drop --stats");
  if (cl.frames && std::abs(cl.time + (*cl.frames - 1) / 60.0) > kMaxTime)
    throw UsageError("--frames " + std::to_string(*cl.frames) + " from --time run past 1e6 seconds");
  if (cl.updateGolden && !cl.golden) throw UsageError("--update-golden needs --golden DIR");
  if (cl.headless && cl.backend == Backend::Window)
    throw UsageError("--headless contradicts --backend window");
  // Validates --variant and --set now, not after start-up. With --scene, the option that picks a
  // light takes any index here: its range is the file's lights, checked when the file is read.
  LessonInfo checked = info;
  if (cl.scene)
    for (Option& o : checked.options)
      if (o.name == info.sceneLightOption) {
        o.min = 0;
        o.max = std::numeric_limits<int>::max();
      }
  addSceneSettings(info, cl);
  optionsFor(checked, cl.variant, cl.settings);
  return cl;
}

void addSceneSettings(const LessonInfo& info, CommandLine& cl) {
  if (!cl.scene) return;
  const std::vector<std::pair<std::string, int>>& ofVariant = findVariant(info, cl.variant).settings;
  const auto gives = [](const std::vector<std::pair<std::string, int>>& settings, const std::string& name) {
    return std::any_of(settings.begin(), settings.end(), [&](const auto& s) { return s.first == name; });
  };
  for (const auto& [name, value] : info.sceneSettings)
    if (!gives(ofVariant, name) && !gives(cl.settings, name)) cl.settings.emplace_back(name, value);
}

std::string variantList(const LessonInfo& info) {
  std::ostringstream out;
  for (const Variant& v : info.variants) {
    // One line a variant, name and help split by a tab: CMake reads this list to make the tests.
    if (v.name.find_first_of(" \t\n") != std::string::npos ||
        v.help.find_first_of("\t\n") != std::string::npos)
      throw std::logic_error("variant '" + v.name + "': its name or help has a tab or a line break");
    out << v.name << "\t" << v.help << "\n";
  }
  return out.str();
}

std::string helpText(const LessonInfo& info, const std::string& program, bool readsScenes) {
  std::ostringstream out;
  out << info.id << ": " << info.title << "\n"
      << info.summary << "\n\n"
      << "usage: " << program << " [flags]\n\n"
      << "Context\n"
      << "  --headless               render off-screen even when a display exists\n"
      << "  --backend NAME           osmesa | egl | window (default: window if a display exists and\n"
      << "                           opens one, else osmesa where built in, else egl)\n"
      << "  --size WxH               framebuffer size (default 640x480)\n"
      << "  --shader-dir DIR         look for shaders here instead of the source tree\n"
      << "                           ($STENCIL_SHADER_DIR does the same; the flag wins)\n"
      << "  --stencil-bits 8|0       0 builds a framebuffer without stencil, to see the check refuse it\n\n"
      << "Window (ignored headless; Page Down and Page Up carry them, and --size, to the next lesson)\n"
      << "  --ui-scale S             panel text, widgets and the stencil legend S times their size,\n"
      << "                           0.5 to 4 (default: the monitor's content scale; 2 for a projector)\n"
      << "  --position X,Y           the window's top left corner on the screen\n"
      << "  --view NAME              colour | stencil | grey | bits | depth (default colour)\n"
      << "  --panel shown|hidden     the panel beside the picture (default shown)\n\n"
      << "What to render\n"
      << "  --time T                 seconds into the animation (default 0), a finite number within\n"
      << "                           -1e6..1e6: beyond that float animation loses its precision\n"
      << "  --frames N               render N frames, 1/60 s apart (default 1 headless; a window\n"
      << "                           runs until closed)\n"
      << "  --variant NAME           a named configuration (default: the first)\n"
      << "  --list-variants          print the variants and exit\n"
      << "  --set NAME=VALUE         set one option after the variant's settings\n";
  if (readsScenes)
    out << "  --scene FILE             render the scene described in FILE (docs/scenes.md) from its\n"
        << "                           camera, instead of the lesson's own scene\n";
  out << "\n"
      << "Output (of the last frame). Every output is checked before anything is rendered: a path\n"
      << "that cannot be written (a folder where a file belongs or a file where a folder does, a\n"
      << "special file, a folder that cannot be made or written, a picture not named .png) is\n"
      << "refused. Each file is written whole or not at all: beside its name, then renamed onto it.\n"
      << "  --out FILE.png           the colour image\n"
      << "  --stencil-out FILE.png   the stencil buffer as a picture with a legend; the raw values\n"
      << "                           go beside it as FILE.raw.png (one grey byte per pixel)\n"
      << "  --stencil-view ramp|bits the picture: colour per value (default) or the 8 bit planes\n"
      << "  --depth-out FILE.png     the depth buffer as a picture (the window's depth view): eye\n"
      << "                           depth, nearest white to farthest dark grey, stretched over\n"
      << "                           the depths present (the range is said on stderr and written\n"
      << "                           under it); blue where the far plane or nothing was drawn\n"
      << "  --passes DIR             colour and stencil after each named pass\n"
      << "  --stats                  JSON on stdout: per pass draw calls, triangles, fragments\n"
      << "                           passed, primitives, GPU and CPU time (null where the driver\n"
      << "                           has no query for it; a GPU time null where it cannot be right,\n"
      << "                           longer than the pass's CPU time or from a timer without bits,\n"
      << "                           with gpu_ms_null_reason), the lesson's own counts\n"
      << "  --stats-frames           --stats without the per-pass queries and glFinish: each frame\n"
      << "                           timed alone, one glFinish at its end (frame_ms, with every\n"
      << "                           frame's time in frame_ms.all and the process's CPU time, every\n"
      << "                           thread's, in frame_cpu_ms.all; draw calls and triangles still\n"
      << "                           counted, samples and GPU times null)\n"
      << "  --quiet                  no context line, no key or progress lines on stderr (errors still)\n";
  if (readsScenes && info.shadows)
    out << "  --mask-out DIR           each light's shadow mask as DIR/light-<i>.png (i from 0): the\n"
        << "                           stencil once that light's shadow is in it, white where it is 0\n"
        << "                           (lit), black elsewhere (of the last frame: headless, or a\n"
        << "                           window with --frames); with --shadow-hours, the sun's mask at\n"
        << "                           each step as DIR/step-HHMM.png\n"
        << "  --shadow-hours FILE.png  a shadow profile (headless): the scene's sun light moved through\n"
        << "                           the day, one frame per step, and for each pixel the steps it\n"
        << "                           spent in shadow, coloured with a legend in hours; the raw counts\n"
        << "                           beside it as FILE.raw.png; one line per step on stderr\n"
        << "  --shadow-span HH:MM-HH:MM  the local times of the first and last step (default 09:00-17:00)\n"
        << "  --shadow-step MINUTES    minutes between steps, 1 to 1440 (default 60)\n";
  if (info.shadows)
    out << "\n"
        << "  --oracle FILE.png        check the shadows against a CPU ray cast of the same scene,\n"
        << "                           pixel by pixel; exit 1 if they differ off the edges; the\n"
        << "                           comparison as a picture (red: wrong, yellow: on an edge);\n"
        << "                           the oracle's classes as raw bytes beside it, FILE.raw.png,\n"
        << "                           and its edges (255: forgiven there), FILE.edges.png\n";
  out << "\n"
      << "Golden tests\n"
      << "  --golden DIR             compare with DIR/VARIANT.png and DIR/VARIANT.stencil.png;\n"
      << "                           exit 1 on a difference, 77 when no context can be made\n"
      << "  --update-golden          write the goldens instead of comparing\n"
      << "  --artifacts DIR          where a failed comparison leaves its images and summary.json\n\n"
      << "Window keys\n";
  for (const WindowKey& k : kWindowKeys) {
    const std::string keys = k.keys;
    out << "  " << keys << std::string(keys.size() < 23 ? 23 - keys.size() : 1, ' ') << "  " << k.what << "\n";
  }
  if (!info.options.empty()) {
    out << "\nOptions (--set NAME=VALUE, or the key in the window)\n";
    for (const Option& o : info.options)
      out << "  " << o.name << " [" << o.key << "] " << optionRange(o) << " (default " << o.value << ")  "
          << o.help
          << (readsScenes && o.name == info.sceneLightOption ? "; with --scene, one of the file's lights"
                                                             : "")
          << "\n";
  }
  out << "\nVariants\n";
  for (const Variant& v : info.variants) out << "  " << v.name << "  " << v.help << "\n";
  out << "\nExit codes: 0 ok, 1 rendering failed or a golden differs, 2 bad input (one line, nothing\n"
      << "written), 77 no GL context (one line).\n";
  return out.str();
}

}  // namespace stencil
