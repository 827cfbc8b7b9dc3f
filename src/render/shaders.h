#pragma once
// GLSL 3.30 sources of the renderer's three programs.
#include "shader_program.h"

namespace animkit::shaders {

/// Lit triangles. Two-sided: the back face shows the back colour with the normal flipped.
/// Light: a key light from above plus a headlight, so no side of an orbited object is black.
inline constexpr ShaderSources lit{
    R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 front;
layout(location = 3) in vec4 back;
uniform mat4 view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec4 v_front;
out vec4 v_back;
void main() {
  v_position = position;
  v_normal = normal;
  v_front = front;
  v_back = back;
  gl_Position = view_projection * vec4(position, 1.0);
})",
    nullptr,
    R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in vec4 v_front;
in vec4 v_back;
uniform vec3 eye;
out vec4 color;
void main() {
  vec3 n = normalize(v_normal);
  vec4 base = v_front;
  if (!gl_FrontFacing) {
    n = -n;
    base = v_back;
  }
  vec3 to_eye = normalize(eye - v_position);
  vec3 key = normalize(vec3(0.35, 1.0, 0.55));
  float diffuse = 0.45 * max(dot(n, key), 0.0) + 0.4 * max(dot(n, to_eye), 0.0);
  float specular = 0.18 * pow(max(dot(reflect(-key, n), to_eye), 0.0), 24.0);
  color = vec4(base.rgb * (0.32 + diffuse) + vec3(specular), base.a);
})"};

/// Vertex stage of lines and markers: a world position, a colour and an on-screen size in
/// pixels (a line's width, a marker's diameter) handed to the geometry stage.
inline constexpr const char* kScreenSizedVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
layout(location = 2) in float size;
uniform mat4 view_projection;
out vec4 v_color;
out float v_size;
void main() {
  v_color = color;
  v_size = size;
  gl_Position = view_projection * vec4(position, 1.0);
})";

/// Lines widened into screen-space quads by a geometry shader: core profiles do not promise
/// glLineWidth above 1. Square caps half a width long close the gaps between polyline joints.
inline constexpr ShaderSources line{
    kScreenSizedVertex,
    R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 viewport;
in vec4 v_color[];
in float v_size[];
out vec4 g_color;
out float g_across;
void main() {
  vec4 a = gl_in[0].gl_Position;
  vec4 b = gl_in[1].gl_Position;
  // Clip against the near plane (z = -w) so a line reaching behind the eye keeps its visible
  // part instead of vanishing (a zoomed-in view of the ground grid).
  float da = a.z + a.w, db = b.z + b.w;
  if (da < 0.0 && db < 0.0) return;
  if (da < 0.0) a = mix(a, b, da / (da - db));
  if (db < 0.0) b = mix(b, a, db / (db - da));
  vec2 half_viewport = 0.5 * viewport;
  vec2 d = (b.xy / b.w - a.xy / a.w) * half_viewport;
  float len = length(d);
  vec2 along = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  float w = 0.5 * v_size[0] + 0.5;  // half a pixel more for the anti-aliased edge
  vec2 cap = along * 0.5 * v_size[0] / half_viewport;
  vec2 side = across * w / half_viewport;
  g_color = v_color[0];
  g_across = -1.0; gl_Position = vec4(a.xy + (-cap - side) * a.w, a.zw); EmitVertex();
  g_across = 1.0;  gl_Position = vec4(a.xy + (-cap + side) * a.w, a.zw); EmitVertex();
  g_color = v_color[1];
  g_across = -1.0; gl_Position = vec4(b.xy + (cap - side) * b.w, b.zw); EmitVertex();
  g_across = 1.0;  gl_Position = vec4(b.xy + (cap + side) * b.w, b.zw); EmitVertex();
  EndPrimitive();
})",
    R"(#version 330 core
in vec4 g_color;
in float g_across;
out vec4 color;
void main() {
  float edge = fwidth(g_across);
  color = vec4(g_color.rgb, g_color.a * (1.0 - smoothstep(1.0 - 1.5 * edge, 1.0, abs(g_across))));
})"};

/// Round markers: each point becomes a screen-aligned square, cut to a disc with a darker rim.
inline constexpr ShaderSources point{
    kScreenSizedVertex,
    R"(#version 330 core
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 viewport;
in vec4 v_color[];
in float v_size[];
out vec4 g_color;
out vec2 g_offset;
void main() {
  vec4 p = gl_in[0].gl_Position;
  if (p.w <= 0.0) return;
  // Offsets are pulled a little towards the eye so a marker wins over the surface it lies on.
  vec2 r = (0.5 * v_size[0] + 0.5) / (0.5 * viewport) * p.w;
  float z = p.z - 0.002 * p.w;
  g_color = v_color[0];
  g_offset = vec2(-1.0, -1.0); gl_Position = vec4(p.x - r.x, p.y - r.y, z, p.w); EmitVertex();
  g_offset = vec2(1.0, -1.0);  gl_Position = vec4(p.x + r.x, p.y - r.y, z, p.w); EmitVertex();
  g_offset = vec2(-1.0, 1.0);  gl_Position = vec4(p.x - r.x, p.y + r.y, z, p.w); EmitVertex();
  g_offset = vec2(1.0, 1.0);   gl_Position = vec4(p.x + r.x, p.y + r.y, z, p.w); EmitVertex();
  EndPrimitive();
})",
    R"(#version 330 core
in vec4 g_color;
in vec2 g_offset;
out vec4 color;
void main() {
  float r = length(g_offset);
  float edge = fwidth(r);
  float alpha = 1.0 - smoothstep(1.0 - 1.5 * edge, 1.0, r);
  if (alpha <= 0.0) discard;
  vec3 rgb = r > 0.72 ? 0.55 * g_color.rgb : g_color.rgb;
  color = vec4(rgb, g_color.a * alpha);
})"};

}  // namespace animkit::shaders
