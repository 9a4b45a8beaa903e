#pragma once
// The microscope viewport: an OpenGL 3.3 core-profile widget that draws shaded meshes
// with per-vertex normals under two lights, seen through an orbiting camera (drag to
// orbit, wheel to zoom). It draws whatever mesh it was last given; the simulation
// never waits on it.

#include "gui/shaded_mesh.h"

#include <QMatrix4x4>
#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>
#include <QPoint>

#include <memory>

namespace microsim::gui {

class Viewport : public QOpenGLWidget, protected QOpenGLExtraFunctions {
  Q_OBJECT

 public:
  explicit Viewport(QWidget* parent = nullptr);
  ~Viewport() override;

  void setMesh(ShadedMesh mesh);
  /// Frames drawn so far (for tests and the status bar).
  int framesDrawn() const { return framesDrawn_; }
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
  void wheelEvent(QWheelEvent* event) override;

 private:
  void uploadMesh();
  void releaseGL();
  QMatrix4x4 viewMatrix() const;

  ShadedMesh mesh_;
  bool meshDirty_ = true;
  int indexCount_ = 0;
  std::unique_ptr<QOpenGLShaderProgram> program_;
  QOpenGLVertexArrayObject vao_;
  QOpenGLBuffer vertexBuffer_{QOpenGLBuffer::VertexBuffer};
  QOpenGLBuffer indexBuffer_{QOpenGLBuffer::IndexBuffer};
  QMatrix4x4 projection_;

  // camera: orbit around the origin (degrees, mm)
  float yaw_ = -30.0f;
  float pitch_ = 25.0f;
  float distance_ = 7.0f;
  QPoint lastMouse_;

  int framesDrawn_ = 0;
  QString lastError_;
};

}  // namespace microsim::gui
