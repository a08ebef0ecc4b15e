// SPDX-License-Identifier: MIT
#pragma once
/// @file render_option.h
/// @brief How a scene is drawn (Open3D's legacy RenderOption), and a geometry's material.
#include <Eigen/Core>
#include <array>
#include <string>

namespace o3d::visualization {

enum class MeshShade { Flat = 0, Smooth = 1 };
/// @brief Open3D's PointColorOption / MeshColorOption values (the JSON files store these numbers).
enum class ColorOption { Default = 0, Color = 1, X = 2, Y = 3, Z = 4, Normal = 9 };

/// @brief One of Open3D's four Phong lights; `position` is relative to the scene's box, in the camera's
/// right/up/front frame, scaled by the box's largest extent.
struct Light {
    Eigen::Vector3d position{0, 0, 2};
    Eigen::Vector3d color{1, 1, 1};
    double diffuse_power = 0.66;
    double specular_power = 0.2;
    double specular_shininess = 100;
};

/// @brief Open3D's RenderOption defaults.
struct RenderOption {
    Eigen::Vector3d background_color{1, 1, 1};
    double point_size = 5;
    double line_width = 1;
    bool light_on = true;
    bool point_show_normal = false;
    bool mesh_show_wireframe = false;
    bool mesh_show_back_face = false;
    MeshShade mesh_shade = MeshShade::Flat;
    ColorOption point_color = ColorOption::Default;
    ColorOption mesh_color = ColorOption::Color;
    Eigen::Vector3d default_mesh_color{0.7, 0.7, 0.7};
    Eigen::Vector3d light_ambient_color{0, 0, 0};
    std::array<Light, 4> lights = {Light{{0, 0, 2}}, Light{{0, 0, 2}}, Light{{0, 0, -2}}, Light{{0, 0, -2}}};
};

/// @brief Throws InvalidArgument naming the first field out of its range (sizes, NaNs, enum values).
void check_render_option(const RenderOption& option);
/// @brief True for the numbers Open3D's color options use (0-4, 9).
bool is_color_option(int value);

/// @brief RenderOption.load_from_json: fields in the file replace those of `option`; throws IoError or
/// ParseError (then `option` is unchanged).
void load_render_option_json(const std::string& path, RenderOption& option);
/// @brief RenderOption.save_to_json in Open3D's layout; throws IoError.
void save_render_option_json(const std::string& path, const RenderOption& option);

enum class Shader { DefaultLit = 0, DefaultUnlit = 1 };

/// @brief A subset of Open3D's rendering.MaterialRecord. Sizes of 0 mean "the RenderOption's".
struct Material {
    Shader shader = Shader::DefaultLit;
    Eigen::Vector4d base_color{1, 1, 1, 1};
    double point_size = 0;
    double line_width = 0;
};

void check_material(const Material& material);

}  // namespace o3d::visualization
