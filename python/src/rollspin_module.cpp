// rollspin._rollspin — the Python door onto the same C++ core as the CLI:
// the scene loader (with --set overrides), the solve and timeline jobs, the
// still, figure and animation jobs. Nothing here reimplements a step; the
// pure-Python package (python/rollspin/) wraps these objects in the public
// API (Scene, Solution, Timeline, Image, Clip). The GIL is released while the
// C++ works; rollspin::Error becomes rollspin.SceneError (bad input) or
// rollspin.RollspinError (runtime), built in rollspin/_errors.py.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <unistd.h>

#include "core/error.hpp"
#include "core/temp_files.hpp"
#include "heap_huge_pages.hpp"
#include "jobs/animation_job.hpp"
#include "jobs/export_job.hpp"
#include "jobs/figure_job.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/remembered_output.hpp"
#include "jobs/render_jobs.hpp"
#include "jobs/scene_print.hpp"
#include "jobs/timeline_csv.hpp"
#include "jobs/viewer_job.hpp"
#include "media/image_io.hpp"
#include "media/sink_factory.hpp"
#include "model/rolling_model.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_catalog.hpp"
#include "scene/scene_loader.hpp"
#include "spin/field.hpp"
#include "spin/su2.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;
using namespace rollspin;

namespace rollspin::python {
// The source tree's scenes/ (generated into source_scenes.cpp by python/CMakeLists.txt).
extern const char* const kSourceScenes;
}  // namespace rollspin::python

namespace {

// Where a scene comes from: a file, or text (loads()), and the --set
// overrides laid over it. Loading it again gives the same scene.
struct SceneSource {
  std::string name;                 // the path as given, or "<string>"
  std::optional<std::string> text;  // loads(): the TOML itself
  std::vector<std::string> overrides;
  std::string sceneName{};  // load_output(): the name the output's job records
};

// One still size and alpha of a scene: the drawing job (spec with the size
// applied, model) and its drawer, kept between stills so that a second still
// costs a solve to s, a DrawList and a GL frame — not a fresh start.
struct StillJob {
  jobs::DrawJobRequest request;
  jobs::DrawJob job;
  std::unique_ptr<draw::SceneDrawer> drawer;
};

// The GL renderer every still shares: one context for the process (a context
// is current on one thread, and the animation and figure jobs make their
// own, so it is dropped before they run and made again after).
struct SharedGl {
  std::mutex mutex;
  std::unique_ptr<jobs::GlRenderer> gl;
  std::thread::id thread;
  std::string key;  // backend | device it was made for
};
SharedGl& sharedGl() {
  static SharedGl* shared = new SharedGl;  // never destroyed: no GL calls at interpreter exit
  return *shared;
}
void dropSharedGl() {
  SharedGl& s = sharedGl();
  if (s.gl && s.thread != std::this_thread::get_id()) (void)s.gl.release();  // not current here: leak, never crash
  s.gl.reset();
}
jobs::GlRenderer& stillRenderer(const scene::SceneSpec& spec) {
  SharedGl& s = sharedGl();
  const std::string key = spec.render.backend.value_or("") + "|" + spec.render.device.value_or("");
  if (!s.gl || s.thread != std::this_thread::get_id() || s.key != key) {
    dropSharedGl();
    (void)python::markHeapForHugePages(spec.render.width, spec.render.height);
    s.gl = std::make_unique<jobs::GlRenderer>(spec, fs::path{});
    s.thread = std::this_thread::get_id();
    s.key = key;
  }
  return *s.gl;
}

class Scene {
 public:
  static std::shared_ptr<Scene> open(SceneSource source) {
    auto scene = std::make_shared<Scene>();
    {
      py::gil_scoped_release release;
      scene->spec_ = source.text ? scene::loadSceneText(*source.text, source.name, source.overrides)
                                 : model::loadScene(source.name, source.overrides);
      if (!source.sceneName.empty()) scene->spec_.name = source.sceneName;
      if (source.text && scene->spec_.name.empty()) scene->spec_.name = "scene";
      scene->model_ = model::buildSceneModel(scene->spec_);
    }
    scene->source_ = std::move(source);
    return scene;
  }

  [[nodiscard]] std::shared_ptr<Scene> withOverrides(const std::vector<std::string>& more) const {
    SceneSource source = source_;
    source.overrides.insert(source.overrides.end(), more.begin(), more.end());
    return open(std::move(source));
  }

  [[nodiscard]] std::string toml() const {
    py::gil_scoped_release release;
    return jobs::resolvedSceneText(source_.name, spec_);
  }

  // (quaternion (4,), method, steps, seconds, length, unitarity error, rotation matrix (3,3),
  //  error estimate of U(L) in radians, its basis).
  [[nodiscard]] py::tuple solve() const {
    spin::SolveStats stats;
    motion::SolverChoice choice;
    {
      py::gil_scoped_release release;
      choice = motion::chooseSolver(spec_, model_);
      stats = motion::solveScene(spec_, model_, choice);
    }
    const spin::Su2& q = stats.final;
    py::array_t<double> quaternion(4);
    double* qd = quaternion.mutable_data();
    qd[0] = q.w, qd[1] = q.x, qd[2] = q.y, qd[3] = q.z;
    py::array_t<double> rotation({3, 3});
    const spin::Mat3 m = q.rotationMatrix();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rotation.mutable_at(i, j) = m(i, j);
    return py::make_tuple(quaternion, std::string(spin::methodName(choice.method)), stats.steps, stats.seconds,
                          model_.path->length(), stats.unitarityError, rotation, stats.errorEstimate,
                          stats.errorEstimateBasis);
  }

  // (column names, values (columns × rows), segment numbers or None, method, steps, seconds,
  // surface indices or None).
  [[nodiscard]] py::tuple timeline() const {
    const spin::SampleArcLengths samples = motion::timelineArcLengths(spec_, model_);
    const auto rows = static_cast<py::ssize_t>(samples.size());
    constexpr auto columns = static_cast<py::ssize_t>(jobs::kTimelineColumns.size());
    py::array_t<double> values({columns, rows});
    const bool segmented = jobs::timelineHasSegments(model_);
    py::array_t<long long> segments(segmented ? rows : 0);
    double* out = values.mutable_data();
    long long* segmentOut = segments.mutable_data();
    const bool surfaced = jobs::timelineHasSurfaces(model_);
    py::array_t<long long> surfaces(surfaced ? rows : 0);
    long long* surfaceOut = surfaces.mutable_data();
    spin::SolveStats stats;
    motion::SolverChoice choice;
    {
      py::gil_scoped_release release;
      choice = motion::chooseSolver(spec_, model_);
      // The step count the solve settles on (refined until its error
      // estimate is met), as `rollspin timeline` samples with.
      (void)motion::solveScene(spec_, model_, choice);
      stats = jobs::sampleTimeline(
          model_, choice, samples,
          [&](std::size_t index, const jobs::TimelineRow& row) {
            for (py::ssize_t c = 0; c < columns; ++c) out[c * rows + static_cast<py::ssize_t>(index)] = row.values[c];
            if (segmented) segmentOut[index] = static_cast<long long>(row.segment);
            if (surfaced) surfaceOut[index] = static_cast<long long>(row.surface);
          },
          source_.name);
    }
    py::list names;
    for (const auto name : jobs::kTimelineColumns) names.append(std::string(name));
    return py::make_tuple(names, values, segmented ? py::object(segments) : py::object(py::none()),
                          std::string(spin::methodName(choice.method)), stats.steps, stats.seconds,
                          surfaced ? py::object(surfaces) : py::object(py::none()));
  }

  // B(s) at each arc length (N × 3), from the field code the solver uses.
  [[nodiscard]] py::array_t<double> field(
      const py::array_t<double, py::array::c_style | py::array::forcecast>& s) const {
    const double length = model_.path->length();
    const auto n = s.size();
    const double* sd = s.data();
    // The argument's name once, as the message's key ("s: expected …").
    for (py::ssize_t k = 0; k < n; ++k)
      if (!std::isfinite(sd[k]) || sd[k] < 0.0 || sd[k] > length)
        throw badInput(SourceLoc{}, "s: expected arc lengths in [0, {}] (the path's length), got {}{}", length, sd[k],
                       n > 1 ? fmt::format(" (s[{}])", k) : std::string());
    py::array_t<double> b({n, py::ssize_t{3}});
    double* bd = b.mutable_data();
    {
      py::gil_scoped_release release;
      for (py::ssize_t k = 0; k < n; ++k) {
        const geometry::Vec3 v = spin::fieldB(model_.path->at(sd[k]), model_.ballRadius);
        bd[3 * k] = v.x(), bd[3 * k + 1] = v.y(), bd[3 * k + 2] = v.z();
      }
    }
    return b;
  }

  // The still job for this size and alpha, made once and kept.
  StillJob& stillJob(std::optional<long long> width, std::optional<long long> height, bool transparent) const {
    const auto key = std::make_tuple(width.value_or(0), height.value_or(0), transparent);
    auto found = stills_.find(key);
    if (found != stills_.end()) return *found->second;
    auto still = std::make_unique<StillJob>();
    still->request = {source_.name, source_.overrides,       {}, width,        height,    transparent,
                      {},           media::OutputUse::Still, 0,  source_.text, spec_.name};
    still->job = jobs::prepareDrawJob(still->request);
    // As `render --still`: a scene with [figure] keys keeps the figure's composition.
    if (jobs::setsFigureKeys(still->job.spec)) still->job.figureText = jobs::fitTextToFigure(still->job.spec);
    still->drawer = jobs::makeDrawer(still->job);
    return *stills_.emplace(key, std::move(still)).first->second;
  }

  [[nodiscard]] const scene::SceneSpec& spec() const { return spec_; }
  [[nodiscard]] const model::RollingModel& model() const { return model_; }
  [[nodiscard]] const SceneSource& source() const { return source_; }

 private:
  SceneSource source_;
  scene::SceneSpec spec_;
  model::RollingModel model_;
  mutable std::map<std::tuple<long long, long long, bool>, std::unique_ptr<StillJob>> stills_;
};

// A still: its pixels, and what drew them (the scene, kept alive, its still
// job and s), so that save() can also draw a PDF/SVG figure of it.
struct Image {
  std::shared_ptr<const Scene> scene;
  const StillJob* still = nullptr;
  media::Image pixels;
  double s = 0.0;
  std::optional<std::string> at;  // as given: the job record of what save() writes

  // What the file remembers, as `render --still` records it: the scene
  // before a figure's text is fitted (loading it lays it out again).
  [[nodiscard]] media::OutputMetadata metadata(const scene::SceneSpec& unfitted, bool figure) const {
    return jobs::outputMetadata(unfitted, still->job.model,
                                {figure ? jobs::JobRecord::Kind::Figure : jobs::JobRecord::Kind::Still, unfitted.name,
                                 at, std::nullopt, jobs::setsFigureKeys(unfitted)});
  }

  [[nodiscard]] fs::path save(const fs::path& path) const {
    py::gil_scoped_release release;
    const scene::SceneSpec& spec = still->job.spec;
    const media::OutputFormat& format = jobs::chooseOutputFormat(spec, path, media::OutputUse::Still);
    if (const auto figure = jobs::figureFormatOf(format)) {
      jobs::checkFigureSpec(spec);
      // Drawn again as `render --still` draws a figure: the text laid out
      // for the printed size, not the pixels'.
      jobs::DrawJob job = jobs::prepareDrawJob(still->request);
      const media::OutputMetadata remembered = metadata(job.spec, true);
      job.figureText = jobs::fitTextToFigure(job.spec);
      const render::DrawList figureList = jobs::makeDrawer(job, s)->draw(jobs::stillFrame(job, s));
      const std::lock_guard lock(sharedGl().mutex);
      dropSharedGl();  // the figure job makes its own context
      jobs::writeFigureStill(job.spec, figureList, path, *figure, {}, &remembered);
      return path;
    }
    media::SinkOptions options = jobs::sinkOptions(spec, path);
    options.metadata = metadata(jobs::prepareDrawJob(still->request).spec, false);
    const auto sink = media::openSink(format, options);
    sink->write(pixels.view());
    return sink->finish();
  }

  [[nodiscard]] py::bytes png() const {
    std::string bytes;
    {
      py::gil_scoped_release release;
      const fs::path file =
          fs::temp_directory_path() / ("rollspin-repr-" + std::to_string(::getpid()) + "-" +
                                       std::to_string(reinterpret_cast<std::uintptr_t>(this)) + ".png");
      media::writePng(file, pixels.view(),
                      still->job.spec.render.transparent ? media::PngChannels::Rgba : media::PngChannels::Rgb);
      std::ifstream in(file, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
      std::error_code ec;
      fs::remove(file, ec);
    }
    return py::bytes(bytes);
  }
};

std::shared_ptr<Image> renderStillImage(const std::shared_ptr<const Scene>& scene, std::optional<std::string> at,
                                        std::optional<long long> width, std::optional<long long> height,
                                        bool transparent) {
  auto image = std::make_shared<Image>();
  image->scene = scene;
  py::gil_scoped_release release;
  const std::lock_guard lock(sharedGl().mutex);  // one GL context, one thread at a time
  const StillJob& still = scene->stillJob(width, height, transparent);
  image->still = &still;
  image->s = jobs::stillArcLength(still.job, at);
  image->at = at;
  // A scene with [figure] keys is framed for each still (as `render --still`):
  // its own drawer, not the one the stills of a size share.
  const render::DrawList list = jobs::setsFigureKeys(still.job.spec)
                                    ? jobs::makeDrawer(still.job, image->s)->draw(jobs::stillFrame(still.job, image->s))
                                    : still.drawer->draw(jobs::stillFrame(still.job, image->s));
  stillRenderer(still.job.spec).renderer.render(list, image->pixels);
  return image;
}

// An animation through the CLI's job: (written ("" for nothing), frames written, frames
// requested, the signal that stopped it or 0).
py::tuple renderClip(const std::shared_ptr<const Scene>& scene, const fs::path& output,
                     std::optional<std::string> frames, std::optional<std::string> quality,
                     std::optional<long long> width, std::optional<long long> height, bool transparent, bool quiet,
                     std::function<void(long long, long long)> onFrame) {
  jobs::AnimationOptions o;
  o.scenePath = scene->source().name;
  o.sceneText = scene->source().text;
  o.sceneName = scene->spec().name;  // a text scene's ("scene", or the name load_output() read)
  o.overrides = scene->source().overrides;
  o.output = output;
  o.frames = std::move(frames);
  o.quality = std::move(quality);
  o.width = width;
  o.height = height;
  o.transparent = transparent;
  o.quiet = quiet;
  o.onFrame = std::move(onFrame);
  jobs::AnimationResult result;
  {
    py::gil_scoped_release release;
    const std::lock_guard lock(sharedGl().mutex);
    dropSharedGl();  // the animation job makes its own context
    (void)python::markHeapForHugePages(width.value_or(scene->spec().render.width),
                                       height.value_or(scene->spec().render.height));
    result = jobs::renderAnimation(o);
  }
  return py::make_tuple(result.written.string(), result.framesWritten, result.framesRequested, result.interruptedBy);
}

// The web viewer's page through the CLI's job (jobs/viewer_job.hpp): the same
// GLB, timeline and page as `rollspin render SCENE -o NAME.html`.
std::string viewerHtml(const std::shared_ptr<const Scene>& scene) {
  py::gil_scoped_release release;
  jobs::DrawJobRequest request;
  request.scenePath = scene->source().name;
  request.sceneText = scene->source().text;
  request.sceneName = scene->spec().name;
  request.overrides = scene->source().overrides;
  request.use = media::OutputUse::Animation;
  return jobs::viewerHtml(jobs::prepareDrawJob(request), scene->source().name);
}

// glTF 2.0 through the CLI's job (jobs/export_job.hpp): the same file as
// `rollspin export SCENE -o PATH`.
std::string exportGltf(const std::shared_ptr<const Scene>& scene, const std::string& path, bool metadata) {
  py::gil_scoped_release release;
  if (!path.empty()) jobs::checkExportOutput(path);
  return jobs::exportGltf({&scene->spec(), scene->source().name, path, metadata}).string();
}

// rollspin::Error → rollspin.SceneError / rollspin.RollspinError with the
// CLI's message (what main() prints after "rollspin: error: ").
void translateErrors() {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      const py::module_ errors = py::module_::import("rollspin._errors");
      const py::object make = errors.attr("_from_core");
      const SourceLoc& at = e.where();
      const py::object error =
          make(e.kind() == ErrorKind::BadInput, std::string(e.what()), e.message(), at.file, at.line, at.column);
      PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
    }
  });
}

}  // namespace

PYBIND11_MODULE(_rollspin, m) {
  m.doc() =
      "rollspin's C++ core (scene loader, solve, timeline, still, figure and animation jobs); "
      "use the `rollspin` package's API, not this module directly.";
  translateErrors();
  m.attr("SOURCE_SCENES") = rollspin::python::kSourceScenes;

  py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene")
      .def_static(
          "load",
          [](const std::string& path, const std::vector<std::string>& overrides) {
            return Scene::open({path, std::nullopt, overrides});
          },
          py::arg("path"), py::arg("overrides") = std::vector<std::string>{})
      .def_static(
          "loads",
          [](const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
            return Scene::open({name, text, overrides});
          },
          py::arg("text"), py::arg("name") = "<string>", py::arg("overrides") = std::vector<std::string>{})
      // An output that remembers its scene (jobs/remembered_output.hpp): a still, figure, clip or timeline.
      .def_static(
          "load_output",
          [](const std::string& path, const std::vector<std::string>& overrides) {
            const jobs::RememberedOutput remembered = jobs::readRememberedOutput(path);
            return Scene::open({remembered.sourceName, remembered.metadata.scene, overrides, remembered.sceneName});
          },
          py::arg("path"), py::arg("overrides") = std::vector<std::string>{})
      .def("with_overrides", &Scene::withOverrides, py::arg("overrides"))
      .def("toml", &Scene::toml)
      .def("solve", &Scene::solve)
      .def("timeline", &Scene::timeline)
      .def("field", &Scene::field, py::arg("s"))
      .def_property_readonly("name", [](const Scene& s) { return s.spec().name; })
      .def_property_readonly("source", [](const Scene& s) { return s.source().name; })
      .def_property_readonly("text", [](const Scene& s) { return s.source().text; })
      .def_property_readonly("overrides", [](const Scene& s) { return s.source().overrides; })
      .def_property_readonly("length", [](const Scene& s) { return s.model().path->length(); })
      .def_property_readonly("ball_radius", [](const Scene& s) { return s.model().ballRadius; })
      .def_property_readonly("describe", [](const Scene& s) { return s.model().path->describe(); })
      .def_property_readonly("azimuth_deg", [](const Scene& s) { return s.spec().render.azimuthDeg; })
      .def_property_readonly("width", [](const Scene& s) { return s.spec().render.width; })
      .def_property_readonly("height", [](const Scene& s) { return s.spec().render.height; });

  py::class_<Image, std::shared_ptr<Image>>(m, "Image")
      .def_property_readonly("width", [](const Image& i) { return i.pixels.width; })
      .def_property_readonly("height", [](const Image& i) { return i.pixels.height; })
      .def_property_readonly("s", [](const Image& i) { return i.s; })
      .def_property_readonly("transparent", [](const Image& i) { return i.still->job.spec.render.transparent; })
      // H × W × 4 uint8, a view of the image's own pixels (kept alive by the array).
      .def_property_readonly(
          "array",
          [](const std::shared_ptr<Image>& i) {
            auto* owner = new std::shared_ptr<Image>(i);
            py::capsule keep(owner, [](void* p) { delete static_cast<std::shared_ptr<Image>*>(p); });
            return py::array_t<std::uint8_t>({i->pixels.height, i->pixels.width, 4}, i->pixels.rgba.data(), keep);
          })
      .def("save", &Image::save, py::arg("path"))
      .def("png", &Image::png);

  // Where a bare scene name is looked for: the package names its own data
  // folders (the executable is python3, whose ../share is not rollspin's).
  m.def(
      "set_scene_folders", [](const std::vector<fs::path>& folders) { scene::setProgramSceneFolders(folders); },
      py::arg("folders"));
  m.def("scene_folders", [] { return scene::sceneFolders(); });
  m.def("scene_search", [] { return scene::sceneSearchText(); });
  // The CLI's spinor angle ψ in [0, 4π) and its axis (`rollspin solve`).
  m.def(
      "spinor_angle",
      [](double w, double x, double y, double z) {
        const spin::Su2 q{w, x, y, z};
        const auto axis = spin::rotationAngleAxis(q).axis;
        return py::make_tuple(spin::spinorAngle(q), py::make_tuple(axis.x(), axis.y(), axis.z()));
      },
      py::arg("qw"), py::arg("qx"), py::arg("qy"), py::arg("qz"));
  m.def("still", &renderStillImage, py::arg("scene"), py::arg("at") = std::nullopt, py::arg("width") = std::nullopt,
        py::arg("height") = std::nullopt, py::arg("transparent") = false);
  m.def("render", &renderClip, py::arg("scene"), py::arg("output"), py::arg("frames") = std::nullopt,
        py::arg("quality") = std::nullopt, py::arg("width") = std::nullopt, py::arg("height") = std::nullopt,
        py::arg("transparent") = false, py::arg("quiet") = true, py::arg("on_frame") = py::none());
  m.def("viewer_html", &viewerHtml, py::arg("scene"));
  m.def("export_gltf", &exportGltf, py::arg("scene"), py::arg("path"), py::arg("metadata") = true);
  m.def(
      "drop_gl",
      [] {
        py::gil_scoped_release release;
        const std::lock_guard lock(sharedGl().mutex);
        dropSharedGl();
      },
      "Destroy the shared still renderer's GL context (a fresh one is made by the next still).");
  m.def(
      "huge_pages_marked", [] { return python::markHeapForHugePages(0, 0); },
      "Bytes of malloc's heap marked for huge pages before the first GL context (0: not applicable here).");
}
