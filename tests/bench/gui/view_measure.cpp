// Measures the microscope viewport (issue #7): its frame rate while the simulation thread runs a
// scene in real time, the simulation's achieved step rate, and the tool-move latency.
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" microsim-view-measure SECONDS [SCENE|none] [WxH]
//       [--idle] [--samples N] [--depth-of-field on|off]
//
// SCENE defaults to resources/scenes/anastomosis.json and WxH to 1280x800; the surface format
// is the app's (gui/render/surface_format.h, N = 4 samples unless --samples says otherwise).
// Three cases:
//   live (default)  the scene is loaded in RealTime mode and SimulationRunner steps it at the
//                   scene's rate while the viewport redraws;
//   --idle          the scene is loaded but never started: the same drawing, no simulation;
//   none            no scene: the viewport's placeholder vessel, no simulation.
// Depth of field as the app picks it on this renderer (render/renderer_probe.h: off on a
// software one) unless --depth-of-field says otherwise.
// The viewport redraws as fast as it can: each presented frame schedules the next update.
//
// Frame rate: frames presented (QOpenGLWidget::frameSwapped, emitted once the top-level window
// has composed the widget's framebuffer and returned from swapBuffers) per second of
// std::chrono::steady_clock, from the first presented frame to the first one past SECONDS.
//
// Latency (live only): a tracker thread of its own (as the OpenIGTLink client has) moves the
// right forceps between two places, each move 100–300 ms (uniformly random, fixed seed) after
// the previous one was presented: the moves fall at random phases of the GUI thread's frames,
// and none is dropped for a slow frame. Clock: std::chrono::steady_clock throughout.
//   start      just before the tracker thread calls SimulationRunner::submitFrame(new pose);
//   drawn      the end of the first paintGL whose snapshot (Viewport::drawnSnapshot) has the
//              right forceps at the new place (within 1e-4 mm);
//   presented  the frameSwapped that follows that paintGL: the frame is on the window.
// In between: the wait for the next 100 Hz step, the step, the snapshot hand-over, the rest of
// the frame in progress, and the frame that shows the move. "drawn" only means the GL commands
// were issued; llvmpipe does most of its rasterising when the frame is flushed, so
// "presented" is the figure.
//
// The machine's load average (/proc/loadavg) is printed before and after, since the figures
// depend on what else runs. A measurement, never a test: nothing is asserted, and it is not
// registered with CTest.
#include "bench_clock.h"
#include "gui/render/renderer_probe.h"
#include "gui/render/surface_format.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFile>
#include <QTimer>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <random>
#include <thread>
#include <vector>

using microsim::bench::quantileMs;
using microsim::gui::SimulationRunner;
using microsim::gui::Viewport;
namespace sim = microsim::sim;
using Clock = std::chrono::steady_clock;

namespace {

double toSeconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

QByteArray loadAverage() {
  QFile file(QStringLiteral("/proc/loadavg"));
  return file.open(QIODevice::ReadOnly) ? file.readLine().trimmed() : QByteArrayLiteral("unknown");
}

// the tracker thread: submits a move, waits until the GUI thread says it was presented, pauses
// a random 100–300 ms, and moves again
class Tracker {
 public:
  explicit Tracker(SimulationRunner* runner) : runner_(runner) {
    frame_.hand(sim::Hand::Right).tracked = true;
    frame_.hand(sim::Hand::Left).tracked = true;
    frame_.hand(sim::Hand::Left).position = Eigen::Vector3d(-1.2, 0.0, 0.8);
  }
  ~Tracker() { stop(); }

  void start() { thread_ = std::thread([this] { run(); }); }
  void stop() {
    {
      const std::lock_guard lock(mutex_);
      quit_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

  /// If a move is waiting to be shown and `shown` is where it went: when it was submitted.
  std::optional<Clock::time_point> pendingMoveAt(const Eigen::Vector3d& shown) {
    const std::lock_guard lock(mutex_);
    if (!pending_ || (shown - places_[place_]).norm() > 1e-4) return std::nullopt;
    return movedAt_;
  }
  /// The pending move is on the window: the next one may follow.
  void presented() {
    {
      const std::lock_guard lock(mutex_);
      pending_ = false;
    }
    wake_.notify_all();
  }

 private:
  const std::array<Eigen::Vector3d, 2> places_{Eigen::Vector3d(1.2, 0.3, 0.8), Eigen::Vector3d(1.2, -0.3, 0.9)};  // mm

  void run() {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> pause(100, 300);  // ms
    const Clock::time_point start = Clock::now();
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return quit_ || !pending_; });
      if (wake_.wait_for(lock, std::chrono::milliseconds(pause(random)), [this] { return quit_; })) return;
      place_ = 1 - place_;
      frame_.time = toSeconds(Clock::now() - start);
      frame_.hand(sim::Hand::Right).position = places_[place_];
      pending_ = true;
      movedAt_ = Clock::now();
      runner_->submitFrame(frame_);
    }
  }

  SimulationRunner* runner_;
  sim::InputFrame frame_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool quit_ = false;
  bool pending_ = false;  // submitted, not yet presented
  int place_ = 0;
  Clock::time_point movedAt_;
};

}  // namespace

int main(int argc, char** argv) {
  // the app's context, before QApplication; --samples is applied below, before any context
  microsim::gui::useMicroscopeSurfaceFormat();
  QApplication app(argc, argv);

  QCommandLineParser parser;
  parser.addPositionalArgument(QStringLiteral("seconds"), QStringLiteral("how long to measure (default 10)"));
  parser.addPositionalArgument(QStringLiteral("scene"), QStringLiteral("scene file, or none (default anastomosis)"));
  parser.addPositionalArgument(QStringLiteral("size"), QStringLiteral("viewport WxH (default 1280x800)"));
  const QCommandLineOption idleOption(QStringLiteral("idle"), QStringLiteral("load the scene but do not run it"));
  const QCommandLineOption samplesOption(QStringLiteral("samples"),
                                         QStringLiteral("multisampling (default what the app picks on this renderer)"),
                                         QStringLiteral("n"));
  const QCommandLineOption focusOption(QStringLiteral("depth-of-field"),
                                      QStringLiteral("blur off the focal plane: on or off (default what the app picks on this renderer)"),
                                      QStringLiteral("on|off"));
  parser.addOption(idleOption);
  parser.addOption(focusOption);
  parser.addOption(samplesOption);
  parser.addHelpOption();
  parser.process(app);
  const QStringList args = parser.positionalArguments();
  const double seconds = !args.empty() ? args[0].toDouble() : 10.0;
  const QString scene = args.size() > 1 ? args[1]
                                        : QStringLiteral(MICROSIM_SOURCE_DIR "/resources/scenes/anastomosis.json");
  int width = 1280;
  int height = 800;
  if (args.size() > 2) {
    const QStringList wh = args[2].split(QLatin1Char('x'));
    bool okWidth = false;
    bool okHeight = false;
    if (wh.size() == 2) {
      width = wh[0].toInt(&okWidth);
      height = wh[1].toInt(&okHeight);
    }
    if (!okWidth || !okHeight || width <= 0 || height <= 0) {
      std::fprintf(stderr, "size must be WxH, not %s\n", qPrintable(args[2]));
      return 2;
    }
  }
  const QString renderer = microsim::gui::openGlRendererName();
  const int samples = parser.isSet(samplesOption) ? parser.value(samplesOption).toInt()
                                                  : microsim::gui::microscopeSamplesFor(renderer);
  std::printf("renderer %s, %d samples\n", qPrintable(renderer), samples);
  microsim::gui::useMicroscopeSurfaceFormat(samples);

  SimulationRunner runner;
  const bool withScene = scene != QStringLiteral("none");
  if (withScene && !runner.load(scene, sim::StepMode::RealTime)) {
    std::fprintf(stderr, "cannot load %s\n", qPrintable(scene));
    return 1;
  }
  const bool live = withScene && !parser.isSet(idleOption);

  Viewport view;
  view.resize(width, height);
  const bool focus = parser.isSet(focusOption) ? parser.value(focusOption) == QStringLiteral("on")
                                               : microsim::gui::depthOfFieldByDefault(renderer);
  view.setDepthOfField(focus);
  std::printf("depth of field %s\n", focus ? "on" : "off");
  if (withScene) view.setRunner(&runner);

  std::vector<double> stepMedians, stepP99s;
  QObject::connect(&runner, &SimulationRunner::stepTimes, &app, [&](double median, double p99) {
    stepMedians.push_back(median / 1e3);
    stepP99s.push_back(p99);
  });

  // the end of the first paintGL that shows the pending move
  Tracker tracker(&runner);
  std::optional<Clock::time_point> drawnMoveAt;
  std::vector<double> toDrawn, toPresented;  // s
  QObject::connect(&view, &Viewport::frameDrawn, &app, [&] {
    if (drawnMoveAt || !view.drawnSnapshot()) return;
    drawnMoveAt = tracker.pendingMoveAt(view.drawnSnapshot()->forceps[1].pose.block<3, 1>(0, 3).cast<double>());
    if (drawnMoveAt) toDrawn.push_back(toSeconds(Clock::now() - *drawnMoveAt));
  });

  int presented = 0;
  int stepsAtStart = 0;
  int stepsAtEnd = 0;
  double elapsed = 0.0;
  bool done = false;
  Clock::time_point measureStart;
  const QByteArray loadBefore = loadAverage();
  QObject::connect(&view, &QOpenGLWidget::frameSwapped, &app, [&] {
    if (done) return;
    const Clock::time_point now = Clock::now();
    if (presented++ == 0) {
      measureStart = now;
      if (live) {
        runner.start();
        tracker.start();
      }
      stepsAtStart = runner.steps();
    }
    if (drawnMoveAt) {
      toPresented.push_back(toSeconds(now - *drawnMoveAt));
      drawnMoveAt.reset();
      tracker.presented();
    }
    elapsed = toSeconds(now - measureStart);
    if (elapsed >= seconds) {
      done = true;
      stepsAtEnd = runner.steps();
      tracker.stop();
      // queued: QApplication::quit closes every window at once, and from a handler inside the
      // viewport's repaint that destroyed the native window Qt was still flushing this frame to
      // (SIGSEGV in QXcbWindow::needsSync)
      QTimer::singleShot(0, &app, [&runner] {
        runner.stop();
        QCoreApplication::quit();
      });
      return;
    }
    QTimer::singleShot(0, &view, qOverload<>(&QWidget::update));
  });

  view.show();
  QApplication::exec();

  const char* mode = live ? "live" : withScene ? "idle (scene loaded, not running)" : "no scene";
  const int frames = presented - 1;
  std::printf("case: %s, viewport %dx%d, %d samples requested; load average before: %s, after: %s\n", mode, width,
              height, samples, loadBefore.constData(), loadAverage().constData());
  std::printf("viewport: %d frames presented in %.2f s = %.1f fps (redrawing continuously; %d paintGL calls)\n",
              frames, elapsed, frames / elapsed, view.framesDrawn());
  if (!live) return 0;
  const int steps = stepsAtEnd - stepsAtStart;
  std::printf("simulation: %d steps in %.2f s = %.1f Hz (scene rate %.0f Hz); step time: median of the per-second "
              "medians %.2f ms, worst per-second p99 %.2f ms\n",
              steps, elapsed, steps / elapsed, runner.sceneDef()->step.rateHz, quantileMs(stepMedians, 0.5),
              stepP99s.empty() ? 0.0 : *std::max_element(stepP99s.begin(), stepP99s.end()));
  std::printf("tool move -> drawn: median %.1f ms, p95 %.1f ms; -> presented: median %.1f ms, p95 %.1f ms, "
              "max %.1f ms over %zu moves\n",
              quantileMs(toDrawn, 0.5), quantileMs(toDrawn, 0.95), quantileMs(toPresented, 0.5),
              quantileMs(toPresented, 0.95), quantileMs(toPresented, 1.0), toPresented.size());
  return 0;
}
