// The structs the shared frame hands to every shader, defined once for C++
// (methods/kit/frame/frame_data.hpp, which checks sizes and offsets) and GLSL
// (methods/kit/frame/scene.glsl). Layout rule: every vec3 is followed by a 4-byte
// scalar and every group of scalars fills 16 bytes, so that std140, std430 and
// C++ (glm, 4-byte aligned) place each member at the same offset.

// The uniform block FrameBlock (std140): the camera and the medium of this frame.
struct FrameData {
  mat4 view_projection;  // world → clip of the camera (the G-buffer pass)
  vec3 eye;              // camera position
  float near_plane;      // view depth of the near plane
  vec3 forward;          // camera basis (geometry::CameraBasis)
  float far_plane;       // view depth of the far plane
  vec3 right;
  float tan_half_fov_y;
  vec3 up;
  float aspect;          // width / height
  vec3 medium_sigma_s;   // 1/m: the medium that fills space
  float shadow_bias;     // in shadow-map texels at the point (scene.glsl)
  vec3 medium_sigma_t;   // 1/m
  float shadow_resolution;  // texels per side of each shadow map
  vec3 ambient;
  float light_model_a0;  // Nilsson eq. 2.13: I / (a1 r² + a0)
  vec2 size;             // width, height in pixels
  float light_model_a1;
  int light_model;       // LightModelType
  int light_count;
  int volume_count;
  int medium_lobes;      // the medium's phase lobes are lobes[0 .. medium_lobes)
  int sparse;            // 1: the grid's pixels are those of its PixelList (pixel.glsl)
};

// One light (std430 array).
struct SceneLight {
  vec3 position;      // point and spot position, or a beam's origin
  float cone;         // spot half-angle (rad)
  vec3 direction;     // spot axis or directional travel (unit)
  float edge;         // spot smooth-edge width (rad)
  vec3 color;         // intensity W/sr (point, spot) or irradiance W/m² (directional)
  float tan_cone;     // tan(cone) for gobo_uv, 0 when cone >= 90°
  vec3 gobo_right;    // the gobo and beam frame (optics::gobo_frame)
  float beam_width;   // m
  vec3 gobo_up;
  float beam_height;  // m
  mat4 shadow_matrix; // world → clip of the 2D shadow map
  int type;           // LIGHT_* (LightType)
  int shadow_kind;    // SHADOW_*
  int shadow_layer;   // 2D map layer, or cube index
  int gobo_layer;     // -1: no gobo
  float texel_per_distance;  // a shadow texel's size at the point is
  float texel_constant;      // (texel_per_distance·distance + texel_constant) / resolution
  float beam_length;  // m along direction; 0: a directional light without a beam
  int gobo_size;      // the gobo's width · 65536 + height: its texels sit at its layer's corner
};

// One bounded box volume (std430 array); its coefficients add to the medium's.
struct SceneVolume {
  vec3 lo;
  int first_lobe;
  vec3 hi;
  int lobe_count;
  vec3 sigma_s;  // 1/m
  float unused_s;
  vec3 sigma_t;  // 1/m
  float unused_t;
};

// One weighted phase lobe (std430 array).
struct SceneLobe {
  int type;  // PHASE_* (optics/phase.glsl)
  float g;
  float weight;
  float unused;
};
