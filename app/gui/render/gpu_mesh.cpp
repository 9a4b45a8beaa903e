#include "gui/render/gpu_mesh.h"

#include <QOpenGLExtraFunctions>

#include <cstddef>

namespace microsim::gui {

namespace {

// GL takes a vertex attribute's byte offset into the bound buffer as a pointer
const void* bufferOffset(std::size_t bytes) {
  return reinterpret_cast<const void*>(bytes);  // NOLINT(performance-no-int-to-ptr): GL's API
}

}  // namespace

bool GpuMesh::create() {
  if (vao_.isCreated()) return true;
  if (!vao_.create() || !vertices_.create() || !colours_.create() || !surface_.create() ||
      !indices_.create()) return false;
  vertices_.setUsagePattern(QOpenGLBuffer::StreamDraw);
  haveIndices_ = false;
  indexCount_ = 0;
  return true;
}

void GpuMesh::destroy() {
  vao_.destroy();
  vertices_.destroy();
  colours_.destroy();
  surface_.destroy();
  indices_.destroy();
  haveIndices_ = false;
  indexCount_ = 0;
}

void GpuMesh::upload(QOpenGLExtraFunctions& gl, const ShadedMesh& mesh, bool indices) {
  QOpenGLVertexArrayObject::Binder bind(&vao_);
  vertices_.bind();
  const auto bytes = static_cast<int>(mesh.vertices.size() * sizeof(ShadedVertex));
  vertices_.allocate(nullptr, bytes);  // orphan the old storage
  vertices_.write(0, mesh.vertices.data(), bytes);
  gl.glEnableVertexAttribArray(0);
  gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ShadedVertex),
                           bufferOffset(offsetof(ShadedVertex, position)));
  gl.glEnableVertexAttribArray(1);
  gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(ShadedVertex),
                           bufferOffset(offsetof(ShadedVertex, normal)));
  if (indices || !haveIndices_) {
    indices_.bind();
    indices_.allocate(mesh.indices.data(), static_cast<int>(mesh.indices.size() * sizeof(std::uint32_t)));
    indexCount_ = static_cast<int>(mesh.indices.size());
    haveIndices_ = true;
  }
}

void GpuMesh::setColours(QOpenGLExtraFunctions& gl, const std::vector<float>& rgb) { attach(gl, colours_, 2, 3, rgb); }

void GpuMesh::setSurface(QOpenGLExtraFunctions& gl, const std::vector<float>& xyzw) { attach(gl, surface_, 3, 4, xyzw); }

void GpuMesh::attach(QOpenGLExtraFunctions& gl, QOpenGLBuffer& buffer, int location, int components,
                     const std::vector<float>& values) {
  QOpenGLVertexArrayObject::Binder bind(&vao_);
  const auto index = static_cast<GLuint>(location);
  if (values.empty()) {
    gl.glDisableVertexAttribArray(index);
    return;
  }
  buffer.bind();
  buffer.allocate(values.data(), static_cast<int>(values.size() * sizeof(float)));
  gl.glEnableVertexAttribArray(index);
  gl.glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, components * static_cast<GLsizei>(sizeof(float)), nullptr);
}

void GpuMesh::draw(QOpenGLExtraFunctions& gl) {
  if (indexCount_ == 0) return;
  QOpenGLVertexArrayObject::Binder bind(&vao_);
  gl.glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace microsim::gui
