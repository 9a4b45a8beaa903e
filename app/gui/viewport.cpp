#include "gui/viewport.h"

#include "gui/render/background_plane.h"
#include "gui/render/marker_meshes.h"
#include "gui/render/renderer_probe.h"
#include "gui/render/shader_program.h"
#include "gui/render/side_view.h"
#include "gui/render/tool_meshes.h"
#include "gui/render/tube_builder.h"
#include "gui/simulation_runner.h"
#include "tracking/held_needle_arc.h"
#include "tracking/manual_source.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QVector4D>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <utility>

namespace microsim::gui {

namespace {

// linear RGB
const QVector3D kBackground(0.07f, 0.06f, 0.06f);
const QVector3D kSideViewBackground(0.13f, 0.12f, 0.12f);
const QVector4D kShadowColour(0.09f, 0.20f, 0.21f, 1.0f);

// mouse gains, sized for a 1 mm vessel under the microscope
constexpr float kMouseOrbitDegPerPixel = 0.15f;
constexpr double kMouseTurnDegPerPixel = 0.5;     // Ctrl + drag, about the needle or the tip
constexpr double kWheelDepthMmPerNotch = 0.1;
constexpr double kWheelNeedleDegPerNotch = 2.0;
constexpr double kMouseClosurePerPixel = 1.0 / 150.0;  // a 150-pixel right drag: open to closed
constexpr int kMouseClickSlopPixels = 3;


}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
  setMinimumSize(320, 240);
  setFocusPolicy(Qt::StrongFocus);
  setMesh(makeVesselPlaceholder());
  mesh(DrawMesh::Ring) = unitRing(kRingTube);
  mesh(DrawMesh::Reticle) = unitRing(kReticleTube);
  mesh(DrawMesh::Arrow) = unitArrow();
  sim::CameraDef placeholder;
  placeholder.eye = sim::Vec3(0.0, -3.0, 7.0);
  placeholder.fovDeg = 30.0;
  camera_.reset(placeholder);
}

Viewport::~Viewport() {
  // the base class destroys the context after this destructor has run; unhook first so its
  // aboutToBeDestroyed signal does not call back into a half-destroyed Viewport
  if (QOpenGLContext* c = context()) disconnect(c, nullptr, this, nullptr);
  releaseGL();
}

void Viewport::setMesh(ShadedMesh placeholder) {
  mesh(DrawMesh::Placeholder) = std::move(placeholder);
  meshChanged(DrawMesh::Placeholder);
  update();
}

void Viewport::setRunner(SimulationRunner* runner) {
  if (runner_) disconnect(runner_, nullptr, this, nullptr);
  runner_ = runner;
  snapshot_.reset();
  if (runner_) {
    // queued: the signal comes from the simulation thread; update() coalesces repeats
    connect(runner_, &SimulationRunner::snapshotReady, this, qOverload<>(&QWidget::update),
            Qt::QueuedConnection);
  }
  sceneChanged();
}

void Viewport::sceneChanged() {
  if (runner_ && runner_->sceneDef()) {
    camera_.reset(runner_->sceneDef()->camera);
    if (manual_) manual_->placeTools(*runner_->sceneDef());
  }
  loadStaticGeometry();
  cameraChanged();
}

void Viewport::setManualSource(tracking::ManualSource* source) {
  manual_ = source;
  cameraChanged();
}

void Viewport::setGuides(std::vector<Guide> guides) {
  guideList_ = std::move(guides);
  update();
}

void Viewport::setStereoMode(StereoMode mode) {
  stereoMode_ = mode;
  update();
}

bool Viewport::quadBufferAvailable() const {
#if QT_VERSION >= QT_VERSION_CHECK(6, 5, 0)
  return format().stereo() && context() && context()->format().stereo();
#else
  return false;  // QOpenGLWidget renders into a texture without left/right buffers before 6.5
#endif
}

StereoMode Viewport::effectiveStereoMode() const {
  if (stereoMode_ == StereoMode::QuadBuffer && !quadBufferAvailable()) return StereoMode::Anaglyph;
  return stereoMode_;
}

void Viewport::setHelpVisible(bool visible) {
  helpVisible_ = visible;
  update();
}

void Viewport::setSideViewVisible(bool visible) {
  sideViewVisible_ = visible;
  update();
}

void Viewport::setDepthOfField(bool on) {
  depthOfField_ = on;
  update();
}

void Viewport::cameraChanged() {
  if (manual_) {
    const auto e = [](const QVector3D& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); };
    manual_->setViewBasis(e(camera_.right()), e(camera_.up()), e(-camera_.forward()));
  }
  update();
}

// ---- geometry ------------------------------------------------------------------------------

void Viewport::loadStaticGeometry() {
  for (DrawMesh m : {DrawMesh::Tissue, DrawMesh::Needle, DrawMesh::Thread, DrawMesh::LeftJaw, DrawMesh::RightJaw,
                     DrawMesh::ScalpelBlade, DrawMesh::ScissorsBlade, DrawMesh::ScissorsShaft, DrawMesh::Background}) {
    mesh(m) = {};
    meshChanged(m);
  }
  tissue_ = {};
  snapshot_.reset();  // the next frame takes the runner's latest onto the new meshes
  if (!runner_ || !runner_->sceneDef()) return;
  const sim::SceneDef& def = *runner_->sceneDef();

  // the tissue's triangles, colours and surface points; its positions come with each snapshot
  tissue_ = tissueSurface(def, runner_->tissueTriangles());
  mesh(DrawMesh::Tissue).indices = tissue_.indices;

  // the tools' meshes in their own frames
  for (int h = 0; h < sim::kHandCount; ++h)
    if (const auto& f = def.forceps[static_cast<std::size_t>(h)]) mesh(jawMeshOf(static_cast<sim::Hand>(h))) = jawMesh(*f);
  if (def.scalpel) mesh(DrawMesh::ScalpelBlade) = scalpelMesh(*def.scalpel);
  if (def.scissors) {
    mesh(DrawMesh::ScissorsBlade) = scissorsBladeMesh(*def.scissors);
    mesh(DrawMesh::ScissorsShaft) = scissorsShaftMesh(*def.scissors);
  }

  BackgroundPlane plane = backgroundPlane(def);
  mesh(DrawMesh::Background) = std::move(plane.mesh);
  shadowMatrix_ = plane.shadow;
}

void Viewport::updateDynamicGeometry() {
  if (!runner_) return;
  std::shared_ptr<const sim::RenderSnapshot> latest = runner_->latestSnapshot();
  if (!latest || latest == snapshot_) return;
  snapshot_ = std::move(latest);
  const sim::RenderSnapshot& s = *snapshot_;

  placeTissue(tissue_, s, mesh(DrawMesh::Tissue));
  tissueMoved_ = true;

  ShadedMesh& needle = mesh(DrawMesh::Needle);
  ShadedMesh& thread = mesh(DrawMesh::Thread);
  needle.vertices.clear();
  needle.indices.clear();
  thread.vertices.clear();
  thread.indices.clear();
  const int sutureNodes = static_cast<int>(s.suturePositions.size() / 3);
  if (sutureNodes > 1) {
    // never thinner than about a pixel, or the thread flickers in and out
    const float pixel = camera_.mmPerPixel(std::max(1, height()));
    // the needle round and smooth enough to keep its curve seen edge-on
    const TubeStyle needleStyle{std::max({2.5f * s.sutureRadius, 0.03f, 1.5f * pixel}), 10, 4};
    const TubeStyle threadStyle{std::max(s.sutureRadius, 0.8f * pixel), 6, 2};
    const int lastNeedle = std::clamp(s.needleNodes - 1, 0, sutureNodes - 1);
    appendTube(s.suturePositions, 0, lastNeedle, s.sutureAlive, needleStyle, needle);
    appendTube(s.suturePositions, lastNeedle, sutureNodes - 1, s.sutureAlive, threadStyle, thread);
  }
  meshChanged(DrawMesh::Needle);
  meshChanged(DrawMesh::Thread);
}

void Viewport::uploadMeshes() {
  for (int i = 0; i < kDrawMeshCount; ++i) {
    const auto m = static_cast<DrawMesh>(i);
    const auto k = static_cast<std::size_t>(i);
    if (meshDirty_[k]) {
      gpu(m).upload(*this, mesh(m), true);
      if (m == DrawMesh::Tissue) {
        gpu(m).setColours(*this, tissue_.colours);
        gpu(m).setSurface(*this, tissue_.surface);
      }
    }
    meshDirty_[k] = false;
  }
  // the tissue moves every step on the same triangles: its vertices only
  if (tissueMoved_) gpu(DrawMesh::Tissue).upload(*this, mesh(DrawMesh::Tissue), false);
  tissueMoved_ = false;
}

// ---- GL ------------------------------------------------------------------------------------

void Viewport::initializeGL() {
  initializeOpenGLFunctions();
  // the context may be re-created (re-parenting); free what belonged to the old one
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGL,
          Qt::UniqueConnection);
  if (!buildPrograms()) return;
  for (GpuMesh& m : gpu_) m.create();
  meshDirty_.fill(true);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);
}

bool Viewport::buildPrograms() {
  // one source, two variants: the tissue's wall shading compiled in only where it is drawn
  const QString vertex = QStringLiteral(":/microsim/shaders/shaded.vert");
  const QString fragment = QStringLiteral(":/microsim/shaders/shaded.frag");
  shaded_ = shaderProgram(vertex, fragment, {}, &lastError_);
  if (shaded_) tissueShaded_ = shaderProgram(vertex, fragment, "#define TISSUE_WALL\n", &lastError_);
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software = isSoftwareRenderer(QString::fromLatin1(renderer ? renderer : ""));
  if (!shaded_ || !tissueShaded_ || !eyepiece_.create(software, &lastError_)) {
    qWarning("viewport: shader program failed: %s", qPrintable(lastError_));
    shaded_.reset();
    tissueShaded_.reset();
    return false;
  }
  return true;
}

void Viewport::releaseGL() {
  if (!shaded_) return;
  makeCurrent();
  for (GpuMesh& m : gpu_) m.destroy();
  eyepiece_.destroy();
  shaded_.reset();
  tissueShaded_.reset();
  doneCurrent();
}

void Viewport::resizeGL(int, int) {}

QRect Viewport::pixelRect(const QRect& logical) const {
  const qreal r = devicePixelRatioF();
  return {qRound(logical.x() * r), qRound(logical.y() * r), qRound(logical.width() * r),
          qRound(logical.height() * r)};
}

void Viewport::setShading(QOpenGLShaderProgram& program, const Material& material) {
  glVertexAttrib3f(2, material.colour.x(), material.colour.y(), material.colour.z());
  program.setUniformValue("specularStrength", material.specular);
  program.setUniformValue("shininess", material.shininess);
}

void Viewport::setDepthCues(float focus, float sharpBand, float fogStart, float fogEnd, bool focusInAlpha,
                            const QRect& fieldArea) {
  const EyepieceField field = fieldArea.isEmpty() ? EyepieceField{} : eyepieceField(fieldArea);
  const QVector4D stop(static_cast<float>(field.centre.x()), static_cast<float>(field.centre.y()), field.radius, field.edge);
  for (QOpenGLShaderProgram* program : {shaded_.get(), tissueShaded_.get()}) {
    program->bind();
    program->setUniformValue("fieldStop", stop);
    program->setUniformValue("focusDepth", focus);
    program->setUniformValue("depthOfField", sharpBand);
    program->setUniformValue("fogStart", fogStart);
    program->setUniformValue("fogEnd", fogEnd);
    program->setUniformValue("fogColour", kBackground);
    program->setUniformValue("focusInAlpha", focusInAlpha);
  }
}

void Viewport::paintGL() {
  if (!shaded_) {
    glClearColor(kBackground.x(), kBackground.y(), kBackground.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ++framesDrawn_;
    Q_EMIT frameDrawn(framesDrawn_);
    return;
  }
  updateDynamicGeometry();
  uploadMeshes();
  const bool live = runner_ && snapshot_ && runner_->sceneDef();
  const DrawList list = live ? buildDrawList(*runner_->sceneDef(), *snapshot_, camera_, guideList_) : placeholderDrawList();

  const QRect full(0, 0, width(), height());
  const StereoMode mode = effectiveStereoMode();
  switch (mode) {
    case StereoMode::Mono:  // NOLINT(bugprone-branch-clone): QuadBuffer differs from Qt 6.5 on
      drawEye(Eye::Centre, full, list);
      break;
    case StereoMode::QuadBuffer:
#if QT_VERSION >= QT_VERSION_CHECK(6, 5, 0)
      drawEye(currentTargetBuffer() == QOpenGLWidget::RightBuffer ? Eye::Right : Eye::Left, full, list);
#else
      drawEye(Eye::Centre, full, list);
#endif
      break;
    case StereoMode::Anaglyph:
      glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
      drawEye(Eye::Left, full, list);
      glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
      drawEye(Eye::Right, full, list);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      break;
    case StereoMode::SideBySide: {
      const int half = width() / 2;
      drawEye(Eye::Left, QRect(0, 0, half, height()), list);
      drawEye(Eye::Right, QRect(half, 0, width() - half, height()), list);
      break;
    }
  }
  if (live && sideViewVisible_ && mode != StereoMode::SideBySide) drawSideView(list);
  const QRect all = pixelRect(full);
  glViewport(all.x(), all.y(), all.width(), all.height());
  drawOverlay();

  drawnStep_ = snapshot_ ? snapshot_->steps : -1;
  ++framesDrawn_;
  Q_EMIT frameDrawn(framesDrawn_);
}

void Viewport::drawEye(Eye eye, const QRect& area, const DrawList& list) {
  const QRect px = pixelRect(area);
  // GL's origin is bottom-left; areas here are full-height, so only x matters
  const QRect glArea(px.x(), 0, px.width(), px.height());
  // with depth of field the eye's picture is drawn offscreen, then blurred into the widget
  const bool blur = depthOfField_ && eyepiece_.begin(*this, pixelRect(rect()).size(), std::max(0, format().samples()));
  glViewport(glArea.x(), glArea.y(), glArea.width(), glArea.height());
  glEnable(GL_SCISSOR_TEST);
  glScissor(glArea.x(), glArea.y(), glArea.width(), glArea.height());
  // black where nothing is drawn, as outside the field stop; for the blur, alpha 0: in focus
  glClearColor(0.0f, 0.0f, 0.0f, blur ? 0.0f : 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  eyepiece_.maskOutsideField(*this, glArea);
  const float aspect = static_cast<float>(area.width()) / static_cast<float>(std::max(1, area.height()));
  const float focus = camera_.focusDistance();
  setDepthCues(focus, std::max(0.3f, 0.025f * camera_.distance()), focus + 0.5f,
               focus + 0.15f * camera_.distance() + 4.0f, blur, glArea);
  drawScene(list, camera_.view(eye), camera_.projection(aspect, eye), true);
  shaded_->release();
  if (blur) eyepiece_.finish(*this, defaultFramebufferObject(), glArea, maxBlurPixels(glArea.height()));
  glDisable(GL_SCISSOR_TEST);
}

void Viewport::drawSideView(const DrawList& list) {
  const QRect area = sideViewArea(size());
  const QRect px = pixelRect(area);
  const int bottom = qRound(height() * devicePixelRatioF()) - px.y() - px.height();  // GL's origin is bottom-left
  glViewport(px.x(), bottom, px.width(), px.height());
  glEnable(GL_SCISSOR_TEST);
  glScissor(px.x(), bottom, px.width(), px.height());
  const float bg = 1.0f / 2.2f;
  glClearColor(std::pow(kSideViewBackground.x(), bg), std::pow(kSideViewBackground.y(), bg),
               std::pow(kSideViewBackground.z(), bg), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const MicroscopeCamera side = sideViewCamera(camera_);
  const float aspect = static_cast<float>(area.width()) / static_cast<float>(std::max(1, area.height()));
  // everything sharp and unfogged: the inset measures height, it is no microscope
  setDepthCues(side.distance(), side.farPlane(), side.farPlane(), 2.0f * side.farPlane(), false, {});
  drawScene(list, side.view(), side.projection(aspect), false);
  shaded_->release();
  glDisable(GL_SCISSOR_TEST);
}

void Viewport::drawScene(const DrawList& list, const QMatrix4x4& view, const QMatrix4x4& projection, bool shadows) {
  for (QOpenGLShaderProgram* program : {shaded_.get(), tissueShaded_.get()}) {
    program->bind();
    program->setUniformValue("view", view);
    program->setUniformValue("projection", projection);
    program->setUniformValue("flatMode", false);
  }
  QOpenGLShaderProgram* bound = tissueShaded_.get();
  bool marks = false;
  for (const DrawItem& item : list) {
    // marks go over the scene: a fresh depth buffer (the eye's scissor holds), so they
    // still hide one another
    if (item.onTop && !marks) {
      glClear(GL_DEPTH_BUFFER_BIT);
      marks = true;
    }
    QOpenGLShaderProgram* program = item.kind == DrawKind::Tissue ? tissueShaded_.get() : shaded_.get();
    if (program != bound) program->bind();
    bound = program;
    setShading(*program, item.material);
    program->setUniformValue("sharp", item.onTop);
    program->setUniformValue("model", item.model);
    program->setUniformValue("normalMatrix", (view * item.model).normalMatrix());
    gpu(item.mesh).draw(*this);
    if (shadows && item.kind == DrawKind::Background) {
      drawShadows(list, view);
      bound = shaded_.get();
    }
  }
}

void Viewport::drawShadows(const DrawList& list, const QMatrix4x4& view) {
  shaded_->bind();
  shaded_->setUniformValue("flatMode", true);
  shaded_->setUniformValue("flatColour", kShadowColour);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -4.0f);  // on the plane, in front of it
  for (const DrawItem& item : shadowCasters(list)) {
    shaded_->setUniformValue("model", shadowMatrix_ * item.model);
    shaded_->setUniformValue("normalMatrix", view.normalMatrix());
    gpu(item.mesh).draw(*this);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  shaded_->setUniformValue("flatMode", false);
}

void Viewport::drawOverlay() {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  font.setPointSizeF(std::max(8.0, font.pointSizeF()));
  painter.setFont(font);
  const QFontMetrics fm(font);
  if (runner_ && snapshot_ && sideViewVisible_ && effectiveStereoMode() != StereoMode::SideBySide) {
    // the inset's frame and name
    const QRect inset = sideViewArea(size());
    painter.setPen(QColor(200, 200, 200, 160));
    painter.drawRect(inset.adjusted(0, 0, -1, -1));
    painter.drawText(inset.left() + 6, inset.bottom() - 6, tr("Side view"));
  }
  if (helpVisible_) {
    const QStringList lines = tracking::ManualSource::keyMapHelp();
    int w = 0;
    for (const QString& l : lines) w = std::max(w, fm.horizontalAdvance(l));
    const QRect box(12, 12, w + 24, fm.height() * static_cast<int>(lines.size()) + 20);
    painter.fillRect(box, QColor(0, 0, 0, 170));
    painter.setPen(QColor(235, 235, 235));
    int y = box.top() + 10 + fm.ascent();
    for (const QString& l : lines) {
      painter.drawText(box.left() + 12, y, l);
      y += fm.height();
    }
  } else {
    painter.setPen(QColor(200, 200, 200, 160));
    painter.drawText(10, height() - 10, tr("F1: keys"));
  }
  if (manual_) {
    const QString hand = manual_->activeHand() == sim::Hand::Left ? tr("Left hand active")
                                                                  : tr("Right hand active");
    // what each hand holds as the scene has it (any source may have swapped it), else as the keys do
    const auto held = [this](sim::Hand h) {
      return snapshot_ ? snapshot_->instruments[static_cast<std::size_t>(h)] : manual_->current().hand(h).instrument;
    };
    const QString tools =
        tr("Left hand: %1 · right hand: %2").arg(instrumentName(held(sim::Hand::Left)), instrumentName(held(sim::Hand::Right)));
    painter.setPen(QColor(220, 220, 220, 200));
    painter.drawText(width() - fm.horizontalAdvance(hand) - 10, height() - 10, hand);
    painter.drawText(width() - fm.horizontalAdvance(tools) - 10, height() - 10 - fm.height(), tools);
  }
  painter.end();
  // QPainter leaves its own state behind; the next frame sets what it needs
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
}

QString Viewport::instrumentName(sim::Instrument instrument) {
  switch (instrument) {
    case sim::Instrument::None: return tr("nothing");
    case sim::Instrument::Forceps: return tr("forceps");
    case sim::Instrument::NeedleHolder: return tr("needle holder");
    case sim::Instrument::Scalpel: return tr("scalpel");
    case sim::Instrument::Scissors: return tr("scissors");
  }
  return {};
}

// ---- input ---------------------------------------------------------------------------------

void Viewport::showView(NamedView view) {
  camera_.showView(view);
  cameraChanged();
}

void Viewport::refreshHeldNeedle() {
  if (!manual_) return;
  const std::shared_ptr<const sim::RenderSnapshot> latest = runner_ ? runner_->latestSnapshot() : nullptr;
  for (const sim::Hand hand : {sim::Hand::Left, sim::Hand::Right})
    manual_->setHeldNeedle(hand, latest ? tracking::heldNeedleArc(*latest, hand) : std::nullopt);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
  lastMouse_ = event->position().toPoint();
  pressMouse_ = lastMouse_;
  if (event->button() == Qt::RightButton) rightDragged_ = false;
  refreshHeldNeedle();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  const QPoint delta = p - lastMouse_;
  lastMouse_ = p;
  const Qt::MouseButtons buttons = event->buttons();
  const bool shift = event->modifiers().testFlag(Qt::ShiftModifier);
  const bool ctrl = event->modifiers().testFlag(Qt::ControlModifier);
  const bool left = buttons.testFlag(Qt::LeftButton);
  if (buttons.testFlag(Qt::MiddleButton) && shift) {
    camera_.pan(static_cast<float>(delta.x()), static_cast<float>(delta.y()), height());
    cameraChanged();
  } else if (buttons.testFlag(Qt::MiddleButton) || (left && (shift || !manual_))) {
    camera_.orbit(kMouseOrbitDegPerPixel * static_cast<float>(delta.x()),
                  kMouseOrbitDegPerPixel * static_cast<float>(delta.y()));
    cameraChanged();
  } else if (left && ctrl) {
    // the larger of the two directions: right or up turns the needle forward
    const int along = std::abs(delta.x()) >= std::abs(delta.y()) ? delta.x() : -delta.y();
    if (!manual_->turnAlongNeedle(kMouseTurnDegPerPixel * along))
      manual_->turnInView(kMouseTurnDegPerPixel * delta.x(), kMouseTurnDegPerPixel * delta.y());
  } else if (left) {
    const double s = camera_.mmPerPixel(height());
    manual_->moveInView(s * delta.x(), -s * delta.y());
  } else if (buttons.testFlag(Qt::RightButton) && manual_) {
    if ((p - pressMouse_).manhattanLength() > kMouseClickSlopPixels) rightDragged_ = true;
    if (rightDragged_ && delta.y() != 0) {
      const double closure = manual_->current().hand(manual_->activeHand()).closure;
      manual_->setClosure(closure + kMouseClosurePerPixel * delta.y());
    }
  }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == Qt::RightButton && manual_ && !rightDragged_) {
    const double closure = manual_->current().hand(manual_->activeHand()).closure;
    manual_->setClosure(closure >= 0.5 ? 0.0 : 1.0);
  }
}

void Viewport::wheelEvent(QWheelEvent* event) {
  // Alt turns a vertical wheel horizontal on some platforms: take whichever axis turned
  const QPoint angle = event->angleDelta();
  const float steps = static_cast<float>(angle.y() != 0 ? angle.y() : angle.x()) / 120.0f;
  const Qt::KeyboardModifiers modifiers = event->modifiers();
  if (modifiers.testFlag(Qt::AltModifier)) {
    camera_.setFocusDistance(camera_.focusDistance() - 0.05f * camera_.distance() * steps);
  } else if (modifiers.testFlag(Qt::ShiftModifier) || !manual_) {
    camera_.zoom(steps);
  } else if (modifiers.testFlag(Qt::ControlModifier)) {
    refreshHeldNeedle();
    manual_->turnAlongNeedle(kWheelNeedleDegPerNotch * steps);
    return;
  } else {
    manual_->moveInDepth(-kWheelDepthMmPerNotch * steps);  // the wheel turned away: deeper
    return;
  }
  cameraChanged();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_F1) {
    if (!event->isAutoRepeat()) setHelpVisible(!helpVisible_);
    return;
  }
  const std::array<std::pair<int, NamedView>, 4> views{{{Qt::Key_Home, NamedView::Microscope},
                                                        {Qt::Key_1, NamedView::Top},
                                                        {Qt::Key_2, NamedView::Oblique},
                                                        {Qt::Key_3, NamedView::Side}}};
  for (const auto& [key, view] : views)
    if (event->key() == key) {
      showView(view);
      return;
    }
  refreshHeldNeedle();
  if (manual_ && manual_->handleKey(event->key(), event->modifiers(), true, event->isAutoRepeat())) {
    update();
    return;
  }
  QOpenGLWidget::keyPressEvent(event);
}

void Viewport::keyReleaseEvent(QKeyEvent* event) {
  if (manual_ && manual_->handleKey(event->key(), event->modifiers(), false, event->isAutoRepeat())) return;
  QOpenGLWidget::keyReleaseEvent(event);
}

// Tab switches hands while a manual source drives the tools, instead of moving the focus
bool Viewport::focusNextPrevChild(bool next) {
  if (manual_) return false;
  return QOpenGLWidget::focusNextPrevChild(next);
}

}  // namespace microsim::gui
