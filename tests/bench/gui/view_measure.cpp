// Measures the microscope viewport while the simulation thread runs a scene in real time:
//   microsim-view-measure [SECONDS=10] [SCENE=resources/scenes/anastomosis.json] [WxH=1280x800]
// prints the viewport's frame rate (redrawing as fast as it can), the simulation's achieved
// step rate and step times, and the latency from a tool move (submitFrame) to the first
// drawn frame whose snapshot shows it. A measurement, never a test: nothing is asserted.
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using microsim::gui::SimulationRunner;
using microsim::gui::Viewport;
namespace sim = microsim::sim;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSwapInterval(0);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);

  const double seconds = argc > 1 ? std::atof(argv[1]) : 10.0;
  const QString scene = argc > 2 ? QString::fromLocal8Bit(argv[2])
                                 : QStringLiteral(MICROSIM_SOURCE_DIR "/resources/scenes/anastomosis.json");
  int width = 1280;
  int height = 800;
  if (argc > 3) std::sscanf(argv[3], "%dx%d", &width, &height);

  SimulationRunner runner;
  sim::SceneError error;
  if (!runner.load(scene, sim::StepMode::RealTime, &error)) {
    std::fprintf(stderr, "cannot load %s\n", qPrintable(scene));
    return 1;
  }
  Viewport view;
  view.resize(width, height);
  view.setRunner(&runner);
  view.show();

  std::vector<double> medians, p99s;
  QObject::connect(&runner, &SimulationRunner::stepTimes, &app, [&](double m, double p) {
    medians.push_back(m);
    p99s.push_back(p);
  });

  // the right forceps jumps between two places every 250 ms; the latency of a jump is the
  // time from submitFrame to the end of the first paint whose snapshot has the tool there
  sim::InputFrame frame;
  frame.hand(sim::Hand::Right).tracked = true;
  frame.hand(sim::Hand::Left).tracked = true;
  frame.hand(sim::Hand::Left).position = Eigen::Vector3d(-1.2, 0.0, 0.8);
  const Eigen::Vector3d places[2] = {Eigen::Vector3d(1.2, 0.3, 0.8), Eigen::Vector3d(1.2, -0.3, 0.9)};
  int place = 0;
  bool pending = false;
  Clock::time_point movedAt;
  std::vector<double> latencies;
  const auto start = Clock::now();
  QTimer mover;
  QObject::connect(&mover, &QTimer::timeout, &app, [&] {
    place = 1 - place;
    frame.time = std::chrono::duration<double>(Clock::now() - start).count();
    frame.hand(sim::Hand::Right).position = places[place];
    movedAt = Clock::now();
    pending = true;
    runner.submitFrame(frame);
  });

  int frames = 0;
  int stepsAtStart = 0;
  Clock::time_point measureStart;
  QObject::connect(&view, &Viewport::frameDrawn, &app, [&] {
    if (frames++ == 0) {
      runner.start();
      mover.start(250);
      measureStart = Clock::now();
      stepsAtStart = runner.steps();
    }
    if (pending && view.drawnSnapshot()) {
      const Eigen::Vector3d shown = view.drawnSnapshot()->forceps[1].pose.block<3, 1>(0, 3).cast<double>();
      if ((shown - places[place]).norm() < 1e-4) {
        latencies.push_back(std::chrono::duration<double, std::milli>(Clock::now() - movedAt).count());
        pending = false;
      }
    }
    if (std::chrono::duration<double>(Clock::now() - measureStart).count() >= seconds) {
      app.quit();
      return;
    }
    QTimer::singleShot(0, &view, qOverload<>(&QWidget::update));  // redraw as fast as possible
  });
  app.exec();

  const double elapsed = std::chrono::duration<double>(Clock::now() - measureStart).count();
  const int steps = runner.steps() - stepsAtStart;
  runner.stop();
  const auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::printf("viewport %dx%d: %d frames in %.2f s = %.1f fps (redrawing continuously)\n", width, height,
              frames - 1, elapsed, (frames - 1) / elapsed);
  std::printf("simulation: %d steps in %.2f s = %.1f Hz (scene rate %.0f Hz); step time median %.2f ms, "
              "worst per-second p99 %.2f ms\n",
              steps, elapsed, steps / elapsed, runner.sceneDef()->step.rateHz, median(medians),
              p99s.empty() ? 0.0 : *std::max_element(p99s.begin(), p99s.end()));
  std::printf("tool move -> first frame showing it: median %.1f ms, max %.1f ms over %zu moves\n",
              median(latencies), latencies.empty() ? 0.0 : *std::max_element(latencies.begin(), latencies.end()),
              latencies.size());
  return 0;
}
