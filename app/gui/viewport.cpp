#include "gui/viewport.h"

#include "gui/render/tube_builder.h"
#include "gui/simulation_runner.h"
#include "tracking/held_needle_arc.h"
#include "tracking/manual_source.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>
#include <QtMath>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace microsim::gui {

namespace {

// linear RGB
const QVector3D kVesselOuter(0.78f, 0.26f, 0.24f);
const QVector3D kVesselLumen(0.50f, 0.07f, 0.12f);
const QVector3D kJawMetal(0.62f, 0.64f, 0.68f);
const QVector3D kNeedleMetal(0.80f, 0.80f, 0.84f);
const QVector3D kThread(0.12f, 0.16f, 0.85f);
const QVector3D kDrape(0.08f, 0.26f, 0.28f);
const QVector3D kGuide(0.15f, 0.95f, 0.35f);
const QVector3D kGuideDone(0.45f, 0.50f, 0.47f);
const QVector3D kBackground(0.07f, 0.06f, 0.06f);

// mouse gains, sized for a 1 mm vessel under the microscope
constexpr float kMouseOrbitDegPerPixel = 0.15f;
constexpr double kMouseTurnDegPerPixel = 0.5;     // Ctrl + drag, about the needle or the tip
constexpr double kWheelDepthMmPerNotch = 0.1;
constexpr double kWheelNeedleDegPerNotch = 2.0;
constexpr double kMouseClosurePerPixel = 1.0 / 150.0;  // a 150-pixel right drag: open to closed
constexpr int kMouseClickSlopPixels = 3;

QVector3D toQt(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

QMatrix4x4 toQt(const Eigen::Matrix4f& m) {
  return QMatrix4x4(m.data()).transposed();  // Eigen is column-major, QMatrix4x4(const float*) row-major
}

// M = (n·L) I − L ⊗ P: projects onto the plane P = (n, d) along the directional light L
QMatrix4x4 planarShadow(const QVector4D& plane, const QVector4D& light) {
  const float dot = QVector4D::dotProduct(plane, light);
  QMatrix4x4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = (r == c ? dot : 0.0f) - light[r] * plane[c];
  return m;
}

void appendCone(const QVector3D& base, const QVector3D& tip, float radius, int sides, ShadedMesh& mesh) {
  const QVector3D axis = (tip - base).normalized();
  const QVector3D any = std::abs(axis.x()) < 0.9f ? QVector3D(1, 0, 0) : QVector3D(0, 1, 0);
  const QVector3D u = QVector3D::crossProduct(axis, any).normalized();
  const QVector3D w = QVector3D::crossProduct(axis, u);
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int s = 0; s < sides; ++s) {
    const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / static_cast<float>(sides);
    const QVector3D radial = std::cos(phi) * u + std::sin(phi) * w;
    const QVector3D p = base + radius * radial;
    const QVector3D n = (radial + 0.3f * axis).normalized();
    mesh.vertices.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}});
    mesh.vertices.push_back({{tip.x(), tip.y(), tip.z()}, {n.x(), n.y(), n.z()}});
  }
  for (int s = 0; s < sides; ++s) {
    const std::uint32_t a = first + 2 * static_cast<std::uint32_t>(s);
    const std::uint32_t b = first + 2 * static_cast<std::uint32_t>((s + 1) % sides);
    mesh.indices.insert(mesh.indices.end(), {a, b, a + 1});
  }
}

void paint(std::vector<float>& colours, std::size_t from, const QVector3D& c) {
  for (std::size_t i = from; i + 2 < colours.size(); i += 3) {
    colours[i] = c.x();
    colours[i + 1] = c.y();
    colours[i + 2] = c.z();
  }
}

}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
  setMinimumSize(320, 240);
  setFocusPolicy(Qt::StrongFocus);
  setMesh(makeVesselPlaceholder());
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

void Viewport::setMesh(ShadedMesh mesh) {
  staticMesh_ = std::move(mesh);
  staticMeshDirty_ = true;
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
  guidesDirty_ = true;
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

void Viewport::cameraChanged() {
  if (manual_) {
    const auto e = [](const QVector3D& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); };
    manual_->setViewBasis(e(camera_.right()), e(camera_.up()), e(-camera_.forward()));
  }
  update();
}

// ---- geometry ------------------------------------------------------------------------------

void Viewport::loadStaticGeometry() {
  tissue_ = {};
  tissueColours_.clear();
  jaw_[0] = {};
  jaw_[1] = {};
  plane_ = {};
  tissueTopologyDirty_ = true;
  jawDirty_ = true;
  if (!runner_ || !runner_->sceneDef()) return;
  const sim::SceneDef& def = *runner_->sceneDef();

  const auto& triangles = runner_->tissueTriangles();
  tissue_.indices.reserve(triangles.size() * 3);
  for (const auto& t : triangles)
    for (int i : t) tissue_.indices.push_back(static_cast<std::uint32_t>(i));
  const auto nodes = static_cast<std::size_t>(def.tissue.model.nodeCount());
  tissueColours_.assign(nodes * 3, 0.0f);
  paint(tissueColours_, 0, kVesselOuter);
  for (const sim::SceneVessel& v : def.vessels) {
    for (int t = v.innerSurface.begin; t < v.innerSurface.end; ++t)
      for (int i : triangles[static_cast<std::size_t>(t)]) {
        const auto k = 3 * static_cast<std::size_t>(i);
        tissueColours_[k] = kVesselLumen.x();
        tissueColours_[k + 1] = kVesselLumen.y();
        tissueColours_[k + 2] = kVesselLumen.z();
      }
  }

  for (int h = 0; h < sim::kHandCount; ++h) {
    const auto& f = def.forceps[static_cast<std::size_t>(h)];
    if (!f) continue;
    std::vector<float> xyz(static_cast<std::size_t>(f->jawVertices.cols()) * 3);
    for (Eigen::Index i = 0; i < f->jawVertices.cols(); ++i)
      for (int r = 0; r < 3; ++r) xyz[static_cast<std::size_t>(3 * i + r)] = static_cast<float>(f->jawVertices(r, i));
    jaw_[h] = meshFromTriangles(xyz, f->jawTriangles);
  }

  // the background plane: behind the tissue as the microscope first sees it, 1 mm past its
  // farthest node, with the scene's shadow projected on it
  const QVector3D eye = toQt(def.camera.eye);
  const QVector3D target = toQt(def.camera.target);
  const QVector3D f = (target - eye).normalized();
  float farthest = 0.0f;
  const auto& rest = def.tissue.model.restPositions();
  for (Eigen::Index i = 0; i < rest.cols(); ++i)
    farthest = std::max(farthest, QVector3D::dotProduct(toQt(Eigen::Vector3d(rest.col(i))) - target, f));
  const QVector3D centre = target + (farthest + 1.0f) * f;
  const QVector3D n = -f;
  const QVector3D any = std::abs(n.x()) < 0.9f ? QVector3D(1, 0, 0) : QVector3D(0, 1, 0);
  const QVector3D u = QVector3D::crossProduct(n, any).normalized() * 40.0f;
  const QVector3D w = QVector3D::crossProduct(n, u.normalized()) * 40.0f;
  for (const QVector3D& p : {centre - u - w, centre + u - w, centre + u + w, centre - u + w})
    plane_.vertices.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}});
  plane_.indices = {0, 1, 2, 0, 2, 3};
  const QVector3D up = toQt(def.camera.up).normalized();
  const QVector3D lightDir = (n + 0.35f * QVector3D::crossProduct(up, n) + 0.5f * up).normalized();
  shadowMatrix_ = planarShadow(QVector4D(n, -QVector3D::dotProduct(n, centre)), QVector4D(lightDir, 0.0f));
}

void Viewport::updateDynamicGeometry() {
  if (!runner_) return;
  std::shared_ptr<const sim::RenderSnapshot> latest = runner_->latestSnapshot();
  if (!latest || latest == snapshot_) return;
  snapshot_ = std::move(latest);
  const sim::RenderSnapshot& s = *snapshot_;

  const std::size_t nodes = s.tissuePositions.size() / 3;
  tissue_.vertices.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    for (int r = 0; r < 3; ++r) {
      tissue_.vertices[i].position[r] = s.tissuePositions[3 * i + static_cast<std::size_t>(r)];
      tissue_.vertices[i].normal[r] = s.tissueNormals[3 * i + static_cast<std::size_t>(r)];
    }
  }

  needle_.vertices.clear();
  needle_.indices.clear();
  thread_.vertices.clear();
  thread_.indices.clear();
  const int sutureNodes = static_cast<int>(s.suturePositions.size() / 3);
  if (sutureNodes > 1) {
    // never thinner than about a pixel, or the thread flickers in and out
    const float pixel = camera_.mmPerPixel(std::max(1, height()));
    TubeStyle needle{std::max({2.5f * s.sutureRadius, 0.03f, 1.5f * pixel}), 8, 2};
    TubeStyle thread{std::max(s.sutureRadius, 0.8f * pixel), 6, 2};
    const int lastNeedle = std::clamp(s.needleNodes - 1, 0, sutureNodes - 1);
    appendTube(s.suturePositions, 0, lastNeedle, s.sutureAlive, needle, needle_);
    appendTube(s.suturePositions, lastNeedle, sutureNodes - 1, s.sutureAlive, thread, thread_);
  }
}

void Viewport::buildGuides() {
  guides_ = {};
  std::vector<float> colours;
  const float pixel = camera_.mmPerPixel(std::max(1, height()));
  for (const Guide& g : guideList_) {
    const std::size_t before = guides_.vertices.size();
    const QVector3D p = toQt(g.point);
    const QVector3D d = toQt(g.direction).normalized();
    const auto size = static_cast<float>(g.size);
    const TubeStyle line{std::max(0.012f, 1.2f * pixel), 6, 1};
    if (g.kind == Guide::Kind::Target) {
      const QVector3D any = std::abs(d.x()) < 0.9f ? QVector3D(1, 0, 0) : QVector3D(0, 1, 0);
      const QVector3D u = QVector3D::crossProduct(d, any).normalized();
      const QVector3D w = QVector3D::crossProduct(d, u);
      std::vector<float> ring;
      constexpr int kSegments = 32;
      for (int k = 0; k <= kSegments; ++k) {
        const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kSegments;
        const QVector3D q = p + size * (std::cos(phi) * u + std::sin(phi) * w);
        ring.insert(ring.end(), {q.x(), q.y(), q.z()});
      }
      appendTube(ring, 0, kSegments, {}, line, guides_);
    } else {
      const QVector3D shaftEnd = p + 0.7f * size * d;
      const std::vector<float> shaft{p.x(), p.y(), p.z(), shaftEnd.x(), shaftEnd.y(), shaftEnd.z()};
      appendTube(shaft, 0, 1, {}, line, guides_);
      appendCone(shaftEnd, p + size * d, 3.0f * line.radius, 10, guides_);
    }
    const QVector3D c = g.done ? kGuideDone : kGuide;
    colours.resize(guides_.vertices.size() * 3);
    paint(colours, before * 3, c);
  }
  if (guidesGpu_.isCreated()) {
    guidesGpu_.upload(*this, guides_, true);
    guidesGpu_.setColours(*this, colours);
  }
  guidesDirty_ = false;
}

// ---- GL ------------------------------------------------------------------------------------

void Viewport::initializeGL() {
  initializeOpenGLFunctions();
  // the context may be re-created (re-parenting); free what belonged to the old one
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGL,
          Qt::UniqueConnection);
  if (!buildPrograms()) return;
  for (GpuMesh* m : {&staticGpu_, &tissueGpu_, &needleGpu_, &threadGpu_, &guidesGpu_, &planeGpu_,
                     &jawGpu_[0], &jawGpu_[1]})
    m->create();
  staticMeshDirty_ = true;
  tissueTopologyDirty_ = true;
  jawDirty_ = true;
  guidesDirty_ = true;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);
}

bool Viewport::buildPrograms() {
  shaded_ = std::make_unique<QOpenGLShaderProgram>();
  const bool ok =
      shaded_->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/microsim/shaders/shaded.vert")) &&
      shaded_->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/microsim/shaders/shaded.frag")) &&
      shaded_->link();
  if (!ok) {
    lastError_ = shaded_->log();
    qWarning("viewport: shader program failed: %s", qPrintable(lastError_));
    shaded_.reset();
  }
  return ok;
}

void Viewport::releaseGL() {
  if (!shaded_) return;
  makeCurrent();
  for (GpuMesh* m : {&staticGpu_, &tissueGpu_, &needleGpu_, &threadGpu_, &guidesGpu_, &planeGpu_,
                     &jawGpu_[0], &jawGpu_[1]})
    m->destroy();
  shaded_.reset();
  doneCurrent();
}

void Viewport::resizeGL(int, int) { guidesDirty_ = true; }

QRect Viewport::pixelRect(const QRect& logical) const {
  const qreal r = devicePixelRatioF();
  return {qRound(logical.x() * r), qRound(logical.y() * r), qRound(logical.width() * r),
          qRound(logical.height() * r)};
}

void Viewport::setShading(const QVector3D& colour, float specular, float shininess) {
  glVertexAttrib3f(2, colour.x(), colour.y(), colour.z());
  shaded_->setUniformValue("specularStrength", specular);
  shaded_->setUniformValue("shininess", shininess);
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
  if (staticMeshDirty_) {
    staticGpu_.upload(*this, staticMesh_, true);
    staticMeshDirty_ = false;
  }
  if (jawDirty_) {
    for (int h = 0; h < 2; ++h) jawGpu_[h].upload(*this, jaw_[h], true);
    planeGpu_.upload(*this, plane_, true);
    jawDirty_ = false;
  }
  if (runner_) {
    tissueGpu_.upload(*this, tissue_, tissueTopologyDirty_);
    if (tissueTopologyDirty_) tissueGpu_.setColours(*this, tissueColours_);
    tissueTopologyDirty_ = false;
    needleGpu_.upload(*this, needle_, true);
    threadGpu_.upload(*this, thread_, true);
  }
  if (guidesDirty_) buildGuides();

  const QRect full(0, 0, width(), height());
  switch (effectiveStereoMode()) {
    case StereoMode::Mono:  // NOLINT(bugprone-branch-clone): QuadBuffer differs from Qt 6.5 on
      drawEye(Eye::Centre, full);
      break;
    case StereoMode::QuadBuffer:
#if QT_VERSION >= QT_VERSION_CHECK(6, 5, 0)
      drawEye(currentTargetBuffer() == QOpenGLWidget::RightBuffer ? Eye::Right : Eye::Left, full);
#else
      drawEye(Eye::Centre, full);
#endif
      break;
    case StereoMode::Anaglyph:
      glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
      drawEye(Eye::Left, full);
      glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
      drawEye(Eye::Right, full);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      break;
    case StereoMode::SideBySide: {
      const int half = width() / 2;
      drawEye(Eye::Left, QRect(0, 0, half, height()));
      drawEye(Eye::Right, QRect(half, 0, width() - half, height()));
      break;
    }
  }
  const QRect all = pixelRect(full);
  glViewport(all.x(), all.y(), all.width(), all.height());
  drawOverlay();

  drawnStep_ = snapshot_ ? snapshot_->steps : -1;
  ++framesDrawn_;
  Q_EMIT frameDrawn(framesDrawn_);
}

void Viewport::drawEye(Eye eye, const QRect& area) {
  const QRect px = pixelRect(area);
  // GL's origin is bottom-left; areas here are full-height, so only x matters
  glViewport(px.x(), 0, px.width(), px.height());
  glEnable(GL_SCISSOR_TEST);
  glScissor(px.x(), 0, px.width(), px.height());
  const float bg = 1.0f / 2.2f;
  glClearColor(std::pow(kBackground.x(), bg), std::pow(kBackground.y(), bg), std::pow(kBackground.z(), bg), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const float aspect = static_cast<float>(area.width()) / static_cast<float>(std::max(1, area.height()));
  drawScene(camera_.view(eye), camera_.projection(aspect, eye));
}

void Viewport::drawScene(const QMatrix4x4& view, const QMatrix4x4& projection) {
  shaded_->bind();
  shaded_->setUniformValue("view", view);
  shaded_->setUniformValue("projection", projection);
  shaded_->setUniformValue("flatMode", false);
  const float focus = camera_.focusDistance();
  shaded_->setUniformValue("focusDepth", focus);
  shaded_->setUniformValue("depthOfField", std::max(0.3f, 0.025f * camera_.distance()));
  shaded_->setUniformValue("fogStart", focus + 0.5f);
  shaded_->setUniformValue("fogEnd", focus + 0.15f * camera_.distance() + 4.0f);
  shaded_->setUniformValue("fogColour", kBackground);

  const auto draw = [&](GpuMesh& mesh, const QMatrix4x4& model) {
    shaded_->setUniformValue("model", model);
    shaded_->setUniformValue("normalMatrix", (view * model).normalMatrix());
    mesh.draw(*this);
  };
  const QMatrix4x4 identity;

  if (!runner_ || !snapshot_) {
    setShading(kVesselOuter, 0.35f, 48.0f);
    draw(staticGpu_, identity);
    shaded_->release();
    return;
  }
  setShading(kDrape, 0.05f, 8.0f);
  draw(planeGpu_, identity);
  drawShadows(view, projection);

  shaded_->setUniformValue("flatMode", false);
  setShading(kVesselOuter, 0.35f, 48.0f);
  draw(tissueGpu_, identity);  // its colour array (outer wall, lumen) overrides the constant
  setShading(kJawMetal, 0.8f, 64.0f);
  for (int h = 0; h < 2; ++h) {
    const sim::ToolSnapshot& t = snapshot_->forceps[static_cast<std::size_t>(h)];
    if (!t.present) continue;
    for (int j = 0; j < 2; ++j) draw(jawGpu_[h], toQt(t.jaws[static_cast<std::size_t>(j)]));
  }
  setShading(kNeedleMetal, 0.9f, 80.0f);
  draw(needleGpu_, identity);
  setShading(kThread, 0.25f, 24.0f);
  draw(threadGpu_, identity);

  if (guidesGpu_.indexCount() > 0) {
    glDepthFunc(GL_ALWAYS);  // marks stay visible through the tissue
    setShading(kGuide, 0.2f, 16.0f);
    draw(guidesGpu_, identity);
    glDepthFunc(GL_LESS);
  }
  shaded_->release();
}

void Viewport::drawShadows(const QMatrix4x4& view, const QMatrix4x4&) {
  shaded_->setUniformValue("flatMode", true);
  shaded_->setUniformValue("flatColour", QVector4D(0.09f, 0.20f, 0.21f, 1.0f));
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -4.0f);  // on the plane, in front of it
  const auto draw = [&](GpuMesh& mesh, const QMatrix4x4& model) {
    shaded_->setUniformValue("model", shadowMatrix_ * model);
    shaded_->setUniformValue("normalMatrix", view.normalMatrix());
    mesh.draw(*this);
  };
  draw(tissueGpu_, {});
  for (int h = 0; h < 2; ++h) {
    const sim::ToolSnapshot& t = snapshot_->forceps[static_cast<std::size_t>(h)];
    if (!t.present) continue;
    for (int j = 0; j < 2; ++j) draw(jawGpu_[h], toQt(t.jaws[static_cast<std::size_t>(j)]));
  }
  draw(needleGpu_, {});
  draw(threadGpu_, {});
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Viewport::drawOverlay() {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  font.setPointSizeF(std::max(8.0, font.pointSizeF()));
  painter.setFont(font);
  const QFontMetrics fm(font);
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
    painter.setPen(QColor(220, 220, 220, 200));
    painter.drawText(width() - fm.horizontalAdvance(hand) - 10, height() - 10, hand);
  }
  painter.end();
  // QPainter leaves its own state behind; the next frame sets what it needs
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
}

// ---- input ---------------------------------------------------------------------------------

void Viewport::showView(NamedView view) {
  camera_.showView(view);
  guidesDirty_ = true;
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
    guidesDirty_ = true;
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
