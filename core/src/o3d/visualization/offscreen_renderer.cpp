// SPDX-License-Identifier: MIT
#include "o3d/visualization/offscreen_renderer.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "o3d/utility/error.h"

namespace o3d::visualization {

/// @brief What the user asked for; resolved against the scene at each render (see visualization.h).
struct OffscreenRenderer::CameraSetting {
    enum class Kind { Default, Pinhole, Lookat, Fov } kind = Kind::Default;
    camera::PinholeCameraParameters pinhole;
    Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero(), up = Eigen::Vector3d::UnitY();
    double scalar = 0;  // zoom, or the field of view
};

namespace {

constexpr int kMaxSize = 16384;

void check_gl(const char* what) {
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", unsigned(error));
        throw std::runtime_error(std::string("OpenGL error ") + code + " in " + what);
    }
}

ColorMode jet_mode(ColorOption option) {
    return option == ColorOption::X ? ColorMode::JetX : option == ColorOption::Y ? ColorMode::JetY : ColorMode::JetZ;
}

}  // namespace

/// @brief What every program gets each frame: the camera, the scene's box, the lights.
struct FrameUniforms {
    Eigen::Matrix4f mvp;
    Eigen::Vector3f eye, ambient, box_min, box_max;
    float light_position[12], light_color[12], light_diffuse[4], light_specular[4], light_shininess[4];
    double extent = 0;
};

namespace {

/// @brief Makes `p` current and sets its uniforms (those the variant lacks have location -1: ignored).
void use_program(const ShaderProgram& p, const FrameUniforms& f, const Material& m, const Eigen::Vector3d& color,
                 float normal_line_length) {
    glUseProgram(p.id);
    glUniformMatrix4fv(p.mvp, 1, GL_FALSE, f.mvp.data());
    glUniform4f(p.base_color, float(m.base_color[0]), float(m.base_color[1]), float(m.base_color[2]),
                float(m.base_color[3]));
    glUniform3f(p.uniform_color, float(color.x()), float(color.y()), float(color.z()));
    glUniform1f(p.normal_line_length, normal_line_length);
    glUniform3fv(p.box_min, 1, f.box_min.data());
    glUniform3fv(p.box_max, 1, f.box_max.data());
    glUniform3fv(p.eye, 1, f.eye.data());
    glUniform3fv(p.ambient, 1, f.ambient.data());
    glUniform3fv(p.light_position, 4, f.light_position);
    glUniform3fv(p.light_color, 4, f.light_color);
    glUniform1fv(p.light_diffuse, 4, f.light_diffuse);
    glUniform1fv(p.light_specular, 4, f.light_specular);
    glUniform1fv(p.light_shininess, 4, f.light_shininess);
}

}  // namespace

/// @brief A context for a renderer of this size (checked first, so a bad size costs no context).
static std::unique_ptr<GLContext> sized_context(int width, int height, Backend backend) {
    if (width < 1 || width > kMaxSize || height < 1 || height > kMaxSize)
        throw InvalidArgument("renderer size must be 1..16384 pixels each way, got " + std::to_string(width) + " x " +
                              std::to_string(height));
    return create_gl_context(backend);
}

OffscreenRenderer::OffscreenRenderer(int width, int height, Backend backend)
    : OffscreenRenderer(width, height, sized_context(width, height, backend)) {}

OffscreenRenderer::OffscreenRenderer(int width, int height, std::unique_ptr<GLContext> context)
    : width_(width), height_(height), context_(std::move(context)), camera_(std::make_unique<CameraSetting>()) {
    if (!context_) throw InvalidArgument("a renderer needs an OpenGL context");
    if (width < 1 || width > kMaxSize || height < 1 || height > kMaxSize)
        throw InvalidArgument("renderer size must be 1..16384 pixels each way, got " + std::to_string(width) + " x " +
                              std::to_string(height));
    backend_ = context_->backend();
    CurrentContext current(*context_);
    programs_.get(ShaderVariant());  // a driver that cannot build o3d's programs fails here, not at the first render
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glGenRenderbuffers(1, &color_buffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_buffer_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_buffer_);
    glGenRenderbuffers(1, &depth_buffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Unsupported("the OpenGL driver cannot make a " + std::to_string(width) + " x " +
                          std::to_string(height) + " RGBA8 + depth32F framebuffer");
    check_gl("creating the framebuffer");
}

OffscreenRenderer::~OffscreenRenderer() {
    if (!context_) return;
    CurrentContext current(*context_);
    for (auto& entry : scene_) entry.second.release();
    outline_.release();
    programs_.release();
    if (depth_buffer_) glDeleteRenderbuffers(1, &depth_buffer_);
    if (color_buffer_) glDeleteRenderbuffers(1, &color_buffer_);
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
}

template <typename Geometry>
void OffscreenRenderer::add(const std::string& name, const Geometry& geometry, const Material& material,
                            bool replace) {
    check_material(material);
    std::lock_guard<std::mutex> lock(mutex_);
    if (name.empty()) throw InvalidArgument("a geometry needs a non-empty name");
    if (!replace && scene_.count(name))
        throw InvalidArgument("a geometry named \"" + name + "\" is already in the scene");
    CurrentContext current(*context_);
    GpuGeometry uploaded = [&] {
        if constexpr (std::is_same_v<Geometry, geometry::Image>) return upload(geometry, width_, height_);
        else return upload(geometry, material);
    }();
    try {
        check_gl("uploading a geometry");
        const auto it = scene_.find(name);
        if (it != scene_.end()) {
            it->second.release();
            it->second = std::move(uploaded);
        } else {
            scene_.emplace(name, std::move(uploaded));
        }
        ++changes_;
    } catch (...) {
        uploaded.release();
        throw;
    }
}

template void OffscreenRenderer::add(const std::string&, const geometry::PointCloud&, const Material&, bool);
template void OffscreenRenderer::add(const std::string&, const geometry::TriangleMesh&, const Material&, bool);
template void OffscreenRenderer::add(const std::string&, const geometry::LineSet&, const Material&, bool);
template void OffscreenRenderer::add(const std::string&, const geometry::VoxelGrid&, const Material&, bool);
template void OffscreenRenderer::add(const std::string&, const geometry::Image&, const Material&, bool);

bool OffscreenRenderer::has(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    return scene_.count(name) > 0;
}

void OffscreenRenderer::remove(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = scene_.find(name);
    if (it == scene_.end()) throw InvalidArgument("no geometry named \"" + name + "\" in the scene");
    CurrentContext current(*context_);
    it->second.release();
    scene_.erase(it);
    ++changes_;
}

void OffscreenRenderer::clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    CurrentContext current(*context_);
    for (auto& entry : scene_) entry.second.release();
    scene_.clear();
    ++changes_;
}

void OffscreenRenderer::set_render_option(const RenderOption& option) {
    check_render_option(option);
    std::lock_guard<std::mutex> lock(mutex_);
    option_ = option;
    ++changes_;
}

void OffscreenRenderer::set_outline(const std::vector<Eigen::Vector2d>& pixels, const Eigen::Vector3d& color) {
    std::lock_guard<std::mutex> lock(mutex_);
    CurrentContext current(*context_);
    outline_.release();
    if (pixels.size() >= 2) outline_ = upload_outline(pixels, width_, height_);
    outline_color_ = color;
    ++changes_;
    check_gl("uploading an outline");
}

void OffscreenRenderer::invalidate() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++changes_;
}

RenderOption OffscreenRenderer::render_option() {
    std::lock_guard<std::mutex> lock(mutex_);
    return option_;
}

void OffscreenRenderer::setup_camera(const camera::PinholeCameraIntrinsic& k, const Eigen::Matrix4d& extrinsic) {
    if (k.width != width_ || k.height != height_)
        throw InvalidArgument("intrinsic is " + std::to_string(k.width) + " x " + std::to_string(k.height) +
                              ", the renderer " + std::to_string(width_) + " x " + std::to_string(height_));
    if (!std::isfinite(k.fx) || !std::isfinite(k.fy) || !std::isfinite(k.cx) || !std::isfinite(k.cy) ||
        !(k.fx > 0) || !(k.fy > 0))
        throw InvalidArgument("intrinsic needs finite values and fx, fy > 0");
    check_rigid(extrinsic);
    std::lock_guard<std::mutex> lock(mutex_);
    const camera::PinholeCameraIntrinsic& old = camera_->pinhole.intrinsic;
    const bool same = camera_->kind == CameraSetting::Kind::Pinhole && old.width == k.width &&
                      old.height == k.height && old.fx == k.fx && old.fy == k.fy && old.cx == k.cx &&
                      old.cy == k.cy && camera_->pinhole.extrinsic == extrinsic;
    if (same) return;  // a viewer aims the camera before every frame: the same view keeps the frame current
    camera_->kind = CameraSetting::Kind::Pinhole;
    camera_->pinhole = {k, extrinsic};
    ++changes_;
}

void OffscreenRenderer::setup_camera_lookat(const Eigen::Vector3d& lookat, const Eigen::Vector3d& front,
                                            const Eigen::Vector3d& up, double zoom) {
    view_from_lookat(lookat, front, up, zoom, SceneBox(), width_, height_);  // validates
    std::lock_guard<std::mutex> lock(mutex_);
    camera_->kind = CameraSetting::Kind::Lookat;
    camera_->a = lookat;
    camera_->b = front;
    camera_->up = up;
    camera_->scalar = zoom;
    ++changes_;
}

void OffscreenRenderer::setup_camera_fov(double fov, const Eigen::Vector3d& center, const Eigen::Vector3d& eye,
                                         const Eigen::Vector3d& up) {
    view_from_eye(fov, center, eye, up, width_, height_);  // validates
    std::lock_guard<std::mutex> lock(mutex_);
    camera_->kind = CameraSetting::Kind::Fov;
    camera_->a = center;
    camera_->b = eye;
    camera_->up = up;
    camera_->scalar = fov;
    ++changes_;
}

camera::PinholeCameraParameters OffscreenRenderer::camera() {
    std::lock_guard<std::mutex> lock(mutex_);
    return resolve_camera(scene_box());
}

SceneBox OffscreenRenderer::scene_bounds() {
    std::lock_guard<std::mutex> lock(mutex_);
    return scene_box();
}

SceneBox OffscreenRenderer::geometry_bounds(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = scene_.find(name);
    if (it == scene_.end()) throw InvalidArgument("no geometry named \"" + name + "\" in the scene");
    return it->second.box;
}

void OffscreenRenderer::blit_to_default_framebuffer() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("copying the frame to the window");
}

SceneBox OffscreenRenderer::scene_box() const {
    SceneBox box;
    for (const auto& entry : scene_) box.add(entry.second.box);
    return box;
}

camera::PinholeCameraParameters OffscreenRenderer::resolve_camera(const SceneBox& box) const {
    const CameraSetting& c = *camera_;
    switch (c.kind) {
        case CameraSetting::Kind::Pinhole: return c.pinhole;
        case CameraSetting::Kind::Lookat: return view_from_lookat(c.a, c.b, c.up, c.scalar, box, width_, height_);
        case CameraSetting::Kind::Fov: return view_from_eye(c.scalar, c.a, c.b, c.up, width_, height_);
        case CameraSetting::Kind::Default: break;
    }
    return view_from_lookat(box.center(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(), kDefaultZoom, box,
                            width_, height_);
}

void OffscreenRenderer::draw_geometry(const GpuGeometry& g, const FrameUniforms& f) {
    const RenderOption& o = option_;
    const Material& m = g.material;
    const bool lit_material = o.light_on && m.shader == Shader::DefaultLit;
    auto use = [&](ColorMode mode, bool lit, const Eigen::Vector3d& color = Eigen::Vector3d::Zero(),
                   float normal_line_length = 0.0f) -> const ShaderProgram& {
        const ShaderProgram& p = programs_.get({mode, lit, normal_line_length > 0.0f});
        use_program(p, f, m, color, normal_line_length);
        return p;
    };
    switch (g.kind) {
        case GeometryKind::Image: {
            // Flat on the frame, under everything else: identity transform, no lights, no depth.
            const ShaderProgram& p = use(ColorMode::Texture, false);
            const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
            glUniformMatrix4fv(p.mvp, 1, GL_FALSE, identity.data());
            glDisable(GL_CULL_FACE);
            glDepthMask(GL_FALSE);
            glDisable(GL_DEPTH_TEST);
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, g.texture);
            glBindVertexArray(g.main.vao);
            glDrawArrays(GL_TRIANGLES, 0, g.main.count);
            glBindTexture(GL_TEXTURE_2D, 0);
            glEnable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
            break;
        }
        case GeometryKind::PointCloud: {
            const double size = m.point_size > 0 ? m.point_size : o.point_size;
            ColorMode mode = jet_mode(o.point_color);
            if (o.point_color == ColorOption::Normal) mode = g.has_normals ? ColorMode::Normal : ColorMode::Uniform;
            else if (o.point_color == ColorOption::Default || o.point_color == ColorOption::Color)
                mode = g.has_colors ? ColorMode::Attribute : ColorMode::JetZ;
            use(mode, lit_material && g.has_normals);  // Open3D lights clouds that have normals
            glDisable(GL_CULL_FACE);
            glPointSize(float(size));
            glBindVertexArray(g.main.vao);
            glDrawArrays(GL_POINTS, 0, g.main.count);
            if (o.point_show_normal && g.normal_lines.vao) {
                use(ColorMode::Uniform, false, Eigen::Vector3d::Zero(), float(size * 0.01 * f.extent));
                glLineWidth(float(m.line_width > 0 ? m.line_width : o.line_width));
                glBindVertexArray(g.normal_lines.vao);
                glDrawArrays(GL_LINES, 0, g.normal_lines.count);
            }
            break;
        }
        case GeometryKind::LineSet:
            use(g.has_colors ? ColorMode::Attribute : ColorMode::Uniform, false);
            glDisable(GL_CULL_FACE);
            glLineWidth(float(m.line_width > 0 ? m.line_width : o.line_width));
            glBindVertexArray(g.main.vao);
            glDrawArrays(GL_LINES, 0, g.main.count);
            break;
        case GeometryKind::TriangleMesh:
        case GeometryKind::VoxelGrid: {
            const bool colored = g.has_colors && (o.mesh_color == ColorOption::Color ||
                                                  (g.kind == GeometryKind::VoxelGrid && o.mesh_color == ColorOption::Default));
            ColorMode mode = jet_mode(o.mesh_color);
            if (o.mesh_color == ColorOption::Normal) mode = ColorMode::Normal;
            else if (o.mesh_color == ColorOption::Default || o.mesh_color == ColorOption::Color)
                mode = colored ? ColorMode::Attribute : ColorMode::Uniform;
            use(mode, lit_material, o.default_mesh_color);
            if (o.mesh_show_back_face) glDisable(GL_CULL_FACE);
            else glEnable(GL_CULL_FACE);
            const bool smooth = o.mesh_shade == MeshShade::Smooth && g.smooth.vao;
            const VertexBuffer& buffer = smooth ? g.smooth : g.main;
            auto draw_buffer = [&] {
                glBindVertexArray(buffer.vao);
                if (buffer.ebo) glDrawElements(GL_TRIANGLES, buffer.count, GL_UNSIGNED_INT, nullptr);
                else glDrawArrays(GL_TRIANGLES, 0, buffer.count);
            };
            if (!o.mesh_show_wireframe) {
                draw_buffer();
                break;
            }
            // Faces pushed back a little so that the edges drawn over them win the depth test.
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(1.0f, 1.0f);
            draw_buffer();
            glDisable(GL_POLYGON_OFFSET_FILL);
            use(ColorMode::Uniform, false);
            glLineWidth(float(m.line_width > 0 ? m.line_width : o.line_width));
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            draw_buffer();
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            break;
        }
    }
    glBindVertexArray(0);
}

std::pair<double, double> OffscreenRenderer::draw_scene() {
    // The scene's box, once a frame: the camera, the depth range, the lights and the color maps follow it.
    const SceneBox box = scene_box();
    const camera::PinholeCameraParameters cam = resolve_camera(box);
    const auto [z_near, z_far] = near_far(cam.extrinsic, box);
    const RenderOption& o = option_;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    glClearColor(float(o.background_color.x()), float(o.background_color.y()), float(o.background_color.z()), 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);

    FrameUniforms f;
    f.mvp = (gl_projection(cam.intrinsic, z_near, z_far) * gl_view(cam.extrinsic)).cast<float>();
    const Eigen::Matrix3d r = cam.extrinsic.block<3, 3>(0, 0);
    const Eigen::Vector3d eye = -r.transpose() * cam.extrinsic.block<3, 1>(0, 3);
    const Eigen::Vector3d right = r.row(0).transpose(), up = -r.row(1).transpose(), front = -r.row(2).transpose();
    f.eye = eye.cast<float>();
    f.ambient = o.light_ambient_color.cast<float>();
    f.box_min = box.min_bound.cast<float>();
    f.box_max = box.max_bound.cast<float>();
    f.extent = box.max_extent();
    for (int i = 0; i < 4; ++i) {
        const Light& light = o.lights[i];
        const Eigen::Vector3d at = box.center() + box.max_extent() * (light.position.x() * right +
                                                                      light.position.y() * up +
                                                                      light.position.z() * front);
        for (int k = 0; k < 3; ++k) {
            f.light_position[3 * i + k] = float(at[k]);
            f.light_color[3 * i + k] = float(light.color[k]);
        }
        f.light_diffuse[i] = float(light.diffuse_power);
        f.light_specular[i] = float(light.specular_power);
        f.light_shininess[i] = float(light.specular_shininess);
    }

    // Images first: they lie flat under the 3D geometry.
    for (const auto& entry : scene_)
        if (entry.second.kind == GeometryKind::Image) draw_geometry(entry.second, f);
    for (const auto& entry : scene_)
        if (entry.second.kind != GeometryKind::Image) draw_geometry(entry.second, f);
    if (outline_.main.vao) {  // over everything: no transform, no depth test
        FrameUniforms flat = f;
        flat.mvp.setIdentity();
        use_program(programs_.get({ColorMode::Uniform, false, false}), flat, Material{}, outline_color_, 0.0f);
        glDisable(GL_DEPTH_TEST);
        glLineWidth(1.0f);
        glBindVertexArray(outline_.main.vao);
        glDrawArrays(GL_LINE_LOOP, 0, outline_.main.count);
        glBindVertexArray(0);
        glEnable(GL_DEPTH_TEST);
    }
    glUseProgram(0);
    glFinish();
    check_gl("drawing the scene");
    drawn_ = changes_;
    drawn_near_far_ = {z_near, z_far};
    return {z_near, z_far};
}

std::pair<double, double> OffscreenRenderer::frame(Frame frame) {
    if (frame == Frame::ReuseIfCurrent && drawn_ == changes_) return drawn_near_far_;
    return draw_scene();
}

geometry::Image OffscreenRenderer::render_to_image(Frame reuse) {
    std::lock_guard<std::mutex> lock(mutex_);
    CurrentContext current(*context_);
    frame(reuse);
    geometry::Image image;
    image.width = width_;
    image.height = height_;
    image.num_channels = 3;
    image.bytes_per_channel = 1;
    image.data.resize(image.byte_size());
    std::vector<uint8_t> rows(image.byte_size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    check_gl("reading the colour buffer");
    // OpenGL's first row is the bottom one; an image's is the top one.
    const size_t line = image.bytes_per_line();
    for (int v = 0; v < height_; ++v)
        std::memcpy(image.data.data() + size_t(v) * line, rows.data() + size_t(height_ - 1 - v) * line, line);
    return image;
}

geometry::Image OffscreenRenderer::render_to_depth_image(bool z_in_view_space, Frame reuse) {
    std::lock_guard<std::mutex> lock(mutex_);
    CurrentContext current(*context_);
    const auto [n, f] = frame(reuse);
    std::vector<float> depth(size_t(width_) * size_t(height_));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    check_gl("reading the depth buffer");
    geometry::Image image;
    image.width = width_;
    image.height = height_;
    image.num_channels = 1;
    image.bytes_per_channel = 4;
    image.data.resize(image.byte_size());
    for (int v = 0; v < height_; ++v) {
        const float* src = depth.data() + size_t(height_ - 1 - v) * size_t(width_);
        float* dst = image.pixel<float>(0, v);
        for (int u = 0; u < width_; ++u) {
            const double d = src[u];
            if (!z_in_view_space) dst[u] = float(d);
            else if (d >= 1.0) dst[u] = 0.0f;  // nothing drawn here
            else dst[u] = float(2.0 * f * n / ((f + n) - (f - n) * (2.0 * d - 1.0)));
        }
    }
    return image;
}

}  // namespace o3d::visualization
