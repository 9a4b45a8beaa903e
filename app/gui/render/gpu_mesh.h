#pragma once
// A ShadedMesh on the GPU: one vertex array with the interleaved position (attribute 0) and
// normal (attribute 1), an optional per-vertex colour (attribute 2; without it the shader's
// constant colour is used), an optional per-vertex surface point and layer (attribute 3, the
// tissue's: render/tissue_surface.h), and the triangle indices. Vertices are re-uploaded every frame
// for what moves (buffer orphaning: the driver never stalls on the previous frame's draw);
// indices only when they change. Needs a current context for every call but the constructor.

#include "gui/shaded_mesh.h"

#include <QOpenGLBuffer>
#include <QOpenGLVertexArrayObject>

#include <vector>

class QOpenGLExtraFunctions;

namespace microsim::gui {

class GpuMesh {
 public:
  bool create();
  void destroy();
  bool isCreated() const { return vao_.isCreated(); }

  /// Uploads the vertices, and the indices too when `indices` is true (or the first time).
  void upload(QOpenGLExtraFunctions& gl, const ShadedMesh& mesh, bool indices);
  /// Per-vertex colours, 3 floats (linear RGB) per vertex; empty: the constant colour.
  void setColours(QOpenGLExtraFunctions& gl, const std::vector<float>& rgb);
  /// Per-vertex surface points and layers, 4 floats per vertex; empty: the shader's constant.
  void setSurface(QOpenGLExtraFunctions& gl, const std::vector<float>& xyzw);
  void draw(QOpenGLExtraFunctions& gl);
  int indexCount() const { return indexCount_; }

 private:
  QOpenGLVertexArrayObject vao_;
  QOpenGLBuffer vertices_{QOpenGLBuffer::VertexBuffer};
  // binds `values` (`components` floats per vertex) to attribute `location`; empty: unbinds
  void attach(QOpenGLExtraFunctions& gl, QOpenGLBuffer& buffer, int location, int components,
              const std::vector<float>& values);

  QOpenGLBuffer colours_{QOpenGLBuffer::VertexBuffer};
  QOpenGLBuffer surface_{QOpenGLBuffer::VertexBuffer};
  QOpenGLBuffer indices_{QOpenGLBuffer::IndexBuffer};
  int indexCount_ = 0;
  bool haveIndices_ = false;
};

}  // namespace microsim::gui
