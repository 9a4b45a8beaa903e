#include "gui/viewport.h"

#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>

namespace microsim::gui {

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
  setMinimumSize(320, 240);
  setFocusPolicy(Qt::StrongFocus);
  setMesh(makeVesselPlaceholder());
}

Viewport::~Viewport() {
  // the base class destroys the context after this destructor has run; unhook first so its
  // aboutToBeDestroyed signal does not call back into a half-destroyed Viewport
  if (QOpenGLContext* c = context()) disconnect(c, nullptr, this, nullptr);
  releaseGL();
}

void Viewport::setMesh(ShadedMesh mesh) {
  mesh_ = std::move(mesh);
  meshDirty_ = true;
  update();
}

void Viewport::initializeGL() {
  initializeOpenGLFunctions();
  // the context may be re-created (re-parenting); free what belonged to the old one
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGL,
          Qt::UniqueConnection);

  program_ = std::make_unique<QOpenGLShaderProgram>();
  const bool ok =
      program_->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/microsim/shaders/shaded.vert")) &&
      program_->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/microsim/shaders/shaded.frag")) &&
      program_->link();
  if (!ok) {
    lastError_ = program_->log();
    qWarning("viewport: shader program failed: %s", qPrintable(lastError_));
    program_.reset();
    return;
  }
  vao_.create();
  vertexBuffer_.create();
  indexBuffer_.create();
  meshDirty_ = true;

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);
}

void Viewport::releaseGL() {
  if (!program_) return;
  makeCurrent();
  vao_.destroy();
  vertexBuffer_.destroy();
  indexBuffer_.destroy();
  program_.reset();
  doneCurrent();
}

void Viewport::uploadMesh() {
  QOpenGLVertexArrayObject::Binder bind(&vao_);
  vertexBuffer_.bind();
  vertexBuffer_.allocate(mesh_.vertices.data(), static_cast<int>(mesh_.vertices.size() * sizeof(ShadedVertex)));
  indexBuffer_.bind();
  indexBuffer_.allocate(mesh_.indices.data(), static_cast<int>(mesh_.indices.size() * sizeof(std::uint32_t)));
  program_->enableAttributeArray(0);
  program_->setAttributeBuffer(0, GL_FLOAT, offsetof(ShadedVertex, position), 3, sizeof(ShadedVertex));
  program_->enableAttributeArray(1);
  program_->setAttributeBuffer(1, GL_FLOAT, offsetof(ShadedVertex, normal), 3, sizeof(ShadedVertex));
  indexCount_ = static_cast<int>(mesh_.indices.size());
  meshDirty_ = false;
}

void Viewport::resizeGL(int width, int height) {
  projection_.setToIdentity();
  projection_.perspective(30.0f, static_cast<float>(width) / std::max(1, height), 0.1f, 200.0f);
}

QMatrix4x4 Viewport::viewMatrix() const {
  QMatrix4x4 view;
  view.translate(0.0f, 0.0f, -distance_);
  view.rotate(pitch_, 1.0f, 0.0f, 0.0f);
  view.rotate(yaw_, 0.0f, 1.0f, 0.0f);
  return view;
}

void Viewport::paintGL() {
  // a dark surgical-field background with a faint warm tint
  glClearColor(0.07f, 0.06f, 0.06f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  if (program_) {
    program_->bind();
    if (meshDirty_) uploadMesh();
    const QMatrix4x4 modelView = viewMatrix();
    program_->setUniformValue("modelView", modelView);
    program_->setUniformValue("projection", projection_);
    program_->setUniformValue("normalMatrix", modelView.normalMatrix());
    program_->setUniformValue("baseColor", QVector3D(0.80f, 0.30f, 0.28f));
    QOpenGLVertexArrayObject::Binder bind(&vao_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    program_->release();
  }
  ++framesDrawn_;
  Q_EMIT frameDrawn(framesDrawn_);
}

void Viewport::mousePressEvent(QMouseEvent* event) { lastMouse_ = event->position().toPoint(); }

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  const QPoint delta = p - lastMouse_;
  lastMouse_ = p;
  if (event->buttons() & Qt::LeftButton) {
    yaw_ += 0.4f * static_cast<float>(delta.x());
    pitch_ = std::clamp(pitch_ + 0.4f * static_cast<float>(delta.y()), -89.0f, 89.0f);
    update();
  }
}

void Viewport::wheelEvent(QWheelEvent* event) {
  const float steps = static_cast<float>(event->angleDelta().y()) / 120.0f;
  distance_ = std::clamp(distance_ * std::pow(0.9f, steps), 1.0f, 60.0f);
  update();
}

}  // namespace microsim::gui
