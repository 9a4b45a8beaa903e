#pragma once
// The microscope viewport: an OpenGL 3.3 core-profile widget that draws the simulation's latest
// RenderSnapshot (DESIGN.md §Data flow): the tissue with per-vertex normals from the snapshot
// and two-sided lighting (the lumen's inner wall has its own colour), the suture and the
// needle as smooth tubes built here from the snapshot's nodes (broken links skipped), the
// forceps jaws from the scene's jaw mesh, the scalpel or the scissors in a hand that holds
// them, and depth cues:
// a background plane under the scene with the scene's projected shadow, darkening with depth
// past the focal plane and a loss of contrast off it, and a side view in the top-right corner
// (render/side_view.h) that shows a tool's height above the tissue. The tissue is shaded as
// wall (render/tissue_surface.h: texture, lumen, cut face), and each eye's picture goes
// through the eyepiece (render/eyepiece_pass.h): blurred off the focal plane (the
// microscope's shallow depth of field, which can be turned off) and seen through a circular
// field stop; the side view is drawn after it, sharp and unmasked. Each forceps' tip is marked where its jaws meet, in the colour of
// what they would close on now, with a ring around it (render/draw_list.h). Learn-mode
// guides are drawn over it; F1 shows the key map; a line at the bottom names what each hand
// holds (as the latest snapshot has it) and which hand is active.
//
// Each frame is one draw list (render/draw_list.h) built from the snapshot; the lit pass, the
// shadow pass, each stereo eye and the side view draw that list.
//
// Mouse, with a manual source (tracking/manual_source.h): the hand first — left drag moves the
// active tool in the view plane (its tip follows the cursor at the target's depth), the wheel
// moves it in depth, Ctrl + left drag or Ctrl + wheel turns the needle it holds along its own
// curve (without a needle Ctrl + drag turns the tool), right drag down/up closes/opens its
// jaws gradually and a right click closes or opens them; the camera second — middle drag or
// Shift + left drag orbits, Shift + middle drag pans, Shift + wheel zooms, Alt + wheel moves
// the focal plane. Without a manual source left drag orbits and the wheel zooms. Keys go to
// the manual source; Home and 1 / 2 / 3 show the named views (render/camera.h: microscope,
// top, oblique, side), F1 toggles the help. Before an input that may turn along the needle,
// the manual source is told what each hand holds in the latest snapshot.
//
// It redraws when the runner publishes a snapshot and reads it without waiting on a step.
// Without a runner it draws the mesh given to setMesh (a placeholder vessel by default).

#include "gui/render/camera.h"
#include "gui/render/draw_list.h"
#include "gui/render/eyepiece_pass.h"
#include "gui/render/gpu_mesh.h"
#include "gui/render/guide.h"
#include "gui/render/stereo_mode.h"
#include "gui/render/tissue_surface.h"
#include "gui/shaded_mesh.h"

#include "microsim/sim/scene/render_snapshot.h"

#include <QMatrix4x4>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLWidget>
#include <QPoint>
#include <QPointer>

#include <array>
#include <memory>
#include <vector>

namespace microsim::tracking {
class ManualSource;
}

namespace microsim::gui {

class SimulationRunner;

class Viewport : public QOpenGLWidget, protected QOpenGLExtraFunctions {
  Q_OBJECT

 public:
  explicit Viewport(QWidget* parent = nullptr);
  ~Viewport() override;

  /// A static mesh to draw while no runner is set.
  void setMesh(ShadedMesh mesh);
  /// Draws this runner's latest snapshot (null: back to the static mesh); resets the camera
  /// to the scene's when it has a scene. The runner must outlive the viewport or be unset.
  void setRunner(SimulationRunner* runner);
  /// Re-reads the runner's static geometry (call after the runner loads another scene).
  void sceneChanged();
  /// The keyboard and right-drag tool source (null: none); kept informed of the view's axes.
  void setManualSource(tracking::ManualSource* source);
  /// Learn-mode marks; an empty list removes them.
  void setGuides(std::vector<Guide> guides);
  /// Requested presentation; QuadBuffer falls back to Anaglyph when unavailable.
  void setStereoMode(StereoMode mode);
  StereoMode stereoMode() const { return stereoMode_; }
  /// What is drawn: the request, or its fallback.
  StereoMode effectiveStereoMode() const;
  /// True when the widget can present left/right buffers (Qt ≥ 6.5 and a stereo format).
  bool quadBufferAvailable() const;
  void setHelpVisible(bool visible);
  bool helpVisible() const { return helpVisible_; }
  /// The side view in the top-right corner (on by default; never in side-by-side stereo,
  /// where it would cover one eye's picture).
  void setSideViewVisible(bool visible);
  bool sideViewVisible() const { return sideViewVisible_; }
  /// Blurs what lies off the focal plane (on by default); off, every depth is sharp.
  void setDepthOfField(bool on);
  bool depthOfField() const { return depthOfField_; }

  /// Shows a named view of the scene (the scene's camera is home).
  void showView(NamedView view);

  MicroscopeCamera& camera() { return camera_; }
  const MicroscopeCamera& camera() const { return camera_; }
  /// Call after changing the camera through camera().
  void cameraChanged();

  /// Frames drawn so far (for tests and the status bar).
  int framesDrawn() const { return framesDrawn_; }
  /// The step count of the snapshot the last frame showed (-1: none).
  int drawnStep() const { return drawnStep_; }
  /// The snapshot the last frame showed (null: none); for measurements and tests.
  const sim::RenderSnapshot* drawnSnapshot() const { return snapshot_.get(); }
  /// An instrument's name as the overlay shows what each hand holds (translated, lower case).
  static QString instrumentName(sim::Instrument instrument);
  /// Empty while the GL pipeline is healthy; otherwise what failed (shader log).
  QString lastError() const { return lastError_; }

  QSize sizeHint() const override { return {800, 600}; }

 Q_SIGNALS:
  void frameDrawn(int frame);

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  bool focusNextPrevChild(bool next) override;

 private:
  void releaseGL();
  bool buildPrograms();
  void loadStaticGeometry();
  void updateDynamicGeometry();
  void uploadMeshes();
  void drawEye(Eye eye, const QRect& area, const DrawList& list);
  void drawSideView(const DrawList& list);
  void drawScene(const DrawList& list, const QMatrix4x4& view, const QMatrix4x4& projection, bool shadows);
  void drawShadows(const DrawList& list, const QMatrix4x4& view);
  void drawOverlay();
  // the focal plane, its sharp band and the fog (mm from the eye) in both programs; with
  // `focusInAlpha` each pixel's alpha says how far out of focus it is, and the field stop is
  // that of `fieldArea` (GL pixels; empty: none) (eyepiece_pass.h)
  void setDepthCues(float focus, float sharpBand, float fogStart, float fogEnd, bool focusInAlpha,
                    const QRect& fieldArea);
  void setShading(QOpenGLShaderProgram& program, const Material& material);
  void refreshHeldNeedle();
  QRect pixelRect(const QRect& logical) const;
  ShadedMesh& mesh(DrawMesh m) { return meshes_[static_cast<std::size_t>(m)]; }
  GpuMesh& gpu(DrawMesh m) { return gpu_[static_cast<std::size_t>(m)]; }
  /// The mesh's vertices and indices go up at the next frame.
  void meshChanged(DrawMesh m) { meshDirty_[static_cast<std::size_t>(m)] = true; }

  // the meshes the draw list names (CPU side), and which changed since the last upload
  std::array<ShadedMesh, kDrawMeshCount> meshes_;
  std::array<bool, kDrawMeshCount> meshDirty_{};
  TissueSurface tissue_;              // the tissue's drawn vertices, colours and surface points
  bool tissueMoved_ = false;          // new positions, same triangles
  QMatrix4x4 shadowMatrix_;

  // GPU side
  std::unique_ptr<QOpenGLShaderProgram> shaded_;        // everything but the tissue
  std::unique_ptr<QOpenGLShaderProgram> tissueShaded_;  // the tissue: its wall's texture and light
  EyepiecePass eyepiece_;
  std::array<GpuMesh, kDrawMeshCount> gpu_;

  QPointer<SimulationRunner> runner_;
  QPointer<tracking::ManualSource> manual_;
  std::shared_ptr<const sim::RenderSnapshot> snapshot_;  // the one being drawn
  std::vector<Guide> guideList_;
  StereoMode stereoMode_ = StereoMode::Mono;
  bool helpVisible_ = false;
  bool sideViewVisible_ = true;
  bool depthOfField_ = true;

  MicroscopeCamera camera_;
  QPoint lastMouse_;
  QPoint pressMouse_;
  bool rightDragged_ = false;  // the right button moved since it was pressed: no click
  int framesDrawn_ = 0;
  int drawnStep_ = -1;
  QString lastError_;
};

}  // namespace microsim::gui
