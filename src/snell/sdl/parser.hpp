#pragma once
// The recursive-descent parser and evaluator. Like POV-Ray it has no syntax tree: directives, macros and
// expressions are evaluated as tokens arrive and scene items are built straight into scene::Scene.
// The member functions are spread over files by concern: token_source.cpp (token stack, directives),
// expressions.cpp (floats, vectors, colours, strings), materials.cpp, objects.cpp, scene_items.cpp.
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "snell/math/pcg32.hpp"
#include "snell/sdl/diagnostics.hpp"
#include "snell/sdl/parse.hpp"
#include "snell/sdl/value.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::geometry {
struct HeightGrid;
}
namespace snell::procedural {
struct Emitter;
class ObjectProbe;
}  // namespace snell::procedural

namespace snell::sdl {

class Parser {
  friend class FunctionCompiler;

 public:
  explicit Parser(const ParseOptions& options);

  scene::Scene parse_file(const std::filesystem::path& path);
  scene::Scene parse_text(const std::string& text, const std::string& file_name);

 private:
  // ---- token source (token_source.cpp) ----
  struct Frame {
    enum class Kind { file, include, macro };
    Kind kind = Kind::file;
    std::shared_ptr<const std::vector<Token>> tokens;
    size_t pos = 0;
    std::filesystem::path folder;  // for #include search
    scene::SourceLocation call_site;
    double saved_version = 0;
    /// A token read ahead of `pos` (an evaluated array element), returned before the stream's next one.
    std::optional<Token> injected;
    /// A macro call: the index of its scope in scopes_, its parameters, and those bound to a caller's
    /// lone identifier (parameter, caller's name), whose values are copied back when the macro ends.
    size_t scope = 0;
    std::vector<std::string> parameters;
    std::vector<std::pair<std::string, std::string>> by_reference;
  };
  struct Cond {
    enum class Kind { if_, while_, switch_, macro_call, for_ };
    Kind kind = Kind::if_;
    size_t frame = 0;
    size_t resume_pos = 0;  // #while: the condition's first token
    long iterations = 0;
    scene::SourceLocation where;
  };

  /// The state of a running `#for`, one per Cond::Kind::for_ on conds_.
  struct ForLoop {
    std::string variable;
    double end = 0;
    double step = 1;
  };

  void push_file(const std::filesystem::path& path, Frame::Kind kind, const scene::SourceLocation& site);
  std::shared_ptr<const std::vector<Token>> tokens_of(const std::string& name, const std::string& text);
  /// The next token with no directive processing (finished include files are left).
  const Token& raw_peek();
  Token raw_next();
  /// The next token after processing directives and expanding macro calls.
  const Token& peek();
  Token next();
  /// Lookahead for an operator or `;` after a value: only the directives that close a block
  /// (#else, #elseif, a macro's or #if's #end) are processed, so a value is stored before the
  /// directives after it run.
  const Token& peek_after_value();
  void handle_directive(const Token& directive);
  void directive_declare(const Token& directive, bool local);
  void directive_if(const Token& directive, bool condition);
  void directive_else(const Token& directive);
  void directive_end(const Token& directive);
  void directive_while(const Token& directive);
  /// `#for (I, start, end [, step])`: a counted loop (POV-Ray 3.7 reference, "The #for Directive").
  void directive_for(const Token& directive);
  /// `#break`: leaves the innermost #switch, #while or #for.
  void directive_break(const Token& directive);
  /// `#default { texture {..} | pigment {..} | finish {..} }`.
  void directive_default(const Token& directive);
  void directive_switch(const Token& directive);
  void directive_macro(const Token& directive);
  void directive_include(const Token& directive);
  void invoke_macro(const Token& name, const std::shared_ptr<const Macro>& macro);
  void end_macro();
  /// Skips raw tokens to the directive (one of `targets`) that closes the current block at this nesting
  /// level; returns it (already consumed).
  Token skip_to(std::initializer_list<const char*> targets, const Token& opener);
  /// Skips a `{ ... }` block whose `{` is next.
  void skip_block(const std::string& what);
  void check_frame_end();
  /// Counts one more token read or skipped against ParseOptions::max_tokens.
  void count_token(const Token& t);

  // ---- user files (file_io.cpp) ----
  /// A file opened by `#fopen`: written through `output`, or read from its lexed tokens.
  struct UserFile {
    std::filesystem::path path;
    std::shared_ptr<std::ofstream> output;
    std::shared_ptr<const std::vector<Token>> input;
    size_t pos = 0;
  };
  /// Where a user file named `name` may be opened: the scene's folder or the temporary folder
  /// (reading also the library paths); anything else is an error.
  std::filesystem::path user_file_path(const std::string& name, const Token& where, bool writing);
  std::vector<std::filesystem::path> user_file_roots(bool writing) const;
  std::optional<std::filesystem::path> find_user_file(const std::string& name, bool writing) const;
  /// `file_exists(name)`: whether the scene could #fopen it for reading.
  bool readable_user_file(const std::string& name) const;
  void directive_fopen(const Token& directive);
  void directive_fclose(const Token& directive);
  void directive_read(const Token& directive);
  void directive_write(const Token& directive);
  UserFile& user_file(const Token& handle);
  /// The next float, vector or string of a data file; nullopt at its end.
  std::optional<Value> read_user_value(UserFile& file);

  // ---- arrays (arrays.cpp) ----
  /// `array[d1][d2]... [{ items }]` after `array`.
  std::shared_ptr<Array> parse_array();
  /// `[i][j]...` after an array's name: the flat index of that element, range-checked.
  size_t parse_array_index(const Array& array, const Token& name);
  /// Replaces `Name[i]...` (its name just read) with a token naming the element's value, so that every
  /// place that accepts an identifier accepts an element too.
  void inject_array_element(const Array& array, const Token& name);
  /// `Name[i]...` after `#ifdef (`: whether that element has been given a value.
  bool array_element_is_set(const Token& name);
  /// `#declare Name[i]... = value`.
  void declare_array_element(const Token& name, bool local);

  // ---- symbols ----
  const Value* lookup(const std::string& name) const;
  /// When the next token names a declared value of type T, consumes it and returns a copy; else nullopt.
  template <typename T>
  std::optional<T> take_declared() {
    const Token& t = peek();
    if (t.kind != Token::Kind::identifier) return std::nullopt;
    const Value* v = lookup(t.text);
    const T* value = v ? std::get_if<T>(&v->data) : nullptr;
    if (!value) return std::nullopt;
    T copy = *value;
    raw_next();
    return copy;
  }
  void declare(const std::string& name, Value value, bool local);

  // ---- diagnostics ----
  [[noreturn]] void fail(const scene::SourceLocation& where, const std::string& message) const;
  void warn(const scene::SourceLocation& where, const std::string& message) const;
  void message(const std::string& text) const;
  std::vector<ChainStep> chain() const;
  /// Charges the scene's memory budget (memory_charges.cpp); past it, an error at `where`.
  memory::Charge charge_memory(const scene::SourceLocation& where, uint64_t bytes, std::string_view consumer);
  /// The same for memory kept as long as the scene (meshes, height fields, images): never given back.
  void keep_memory(const scene::SourceLocation& where, uint64_t bytes, std::string_view consumer);
  /// Runs `parse`, turning a BudgetExceeded from below (an array copied) into an error at the next token.
  void locate_memory_errors(const std::function<void()>& parse);

  // ---- expressions (expressions.cpp) ----
  Numeric parse_numeric();
  /// An argument of a scene item: arithmetic only (`+ - * /`, unary, parentheses), as POV-Ray's
  /// Parse_Float/Parse_Vector read it, so `box { <0,0,0><1,1,1> }` is two vectors, not a comparison.
  /// Comparisons, `&`, `|` and `?:` are read inside parentheses, vector components and arguments.
  double parse_float();
  /// A float used as a count or index, truncated as POV-Ray's (int) casts do; outside [lo, hi] (or NaN)
  /// it is an error, never an out-of-range conversion.
  int parse_int(const char* what, int lo = std::numeric_limits<int>::min(),
                int hi = std::numeric_limits<int>::max());
  /// A directive's value (`#if`, `#while`, `#switch`...): a full expression.
  double parse_directive_float();
  Numeric parse_argument_numeric();
  math::Vec3 parse_vector();
  /// A float or vector, promoted to a colour (POV-Ray's colour expression with rgb/red/... keywords).
  material::Rgbft parse_color();
  std::string parse_string();
  // ---- strings (strings.cpp) ----
  /// The function after its name and `(`: concat, str, vstr, chr, substr, strupr, strlwr, datetime.
  std::string parse_string_function(const Token& name);
  /// strlen, strcmp, val, asc, file_exists: numbers computed from strings.
  Numeric parse_string_query(const Token& name);
  bool parse_bool_optional(bool if_absent);
  bool starts_string();
  bool starts_numeric();
  Value parse_rvalue();
  Numeric parse_ternary();
  Numeric parse_or();
  Numeric parse_and();
  Numeric parse_comparison();
  Numeric parse_additive();
  Numeric parse_multiplicative();
  Numeric parse_unary();
  Numeric parse_postfix();
  Numeric parse_primary();
  Numeric parse_color_keywords();
  /// The built-in float constants (`pi`, `true`, `version`, `clock`, `image_width`...), or nothing.
  std::optional<double> builtin_constant(const std::string& word) const;
  Numeric parse_function(const Token& name);
  /// `dimensions(A)`, `dimension_size(A, n)` (arrays.cpp).
  Numeric parse_array_function(const Token& name);
  /// `seed(n)`, `rand(stream)` (random.cpp).
  Numeric parse_random_function(const Token& name);
  void expect(const char* symbol, const char* context);
  Token expect_identifier(const char* context);
  bool accept(const char* symbol);

  // ---- object queries (object_queries.cpp) ----
  /// `trace(...)`, `min_extent(...)`, `max_extent(...)` after the function's name.
  Numeric parse_object_query(const Token& name);
  ParsedObject parse_object_argument(const char* function_name);
  /// An object (declared or written out) as an inside test in world space, for the object pattern.
  std::function<bool(const math::Vec3&)> parse_inside_test();
  /// `{ Blob_or_Isosurface } [threshold bool]` after `potential`: the field as a pattern
  /// (potential_pattern.cpp).
  std::shared_ptr<const texture::ValuePattern> parse_potential_pattern();
  /// Sets an existing identifier where it lives, or declares a global one (#read, trace's normal).
  void assign(const std::string& name, Value value);

  // ---- splines (spline_block.cpp) ----
  /// `{ [Spline] [linear_spline|quadratic_spline|cubic_spline|natural_spline] t, value ... }`.
  std::shared_ptr<const Spline> parse_spline_block();
  /// `(t [, kind])` after a spline's name: its value there.
  Numeric call_spline(const Token& name, const Spline& spline);

  // ---- user functions (function_compiler.cpp) ----
  /// `[(params)] { body }` after the `function` keyword (also for isosurface's `function { ... }`).
  std::shared_ptr<const function::Function> parse_function_block();
  /// `{ ... }` after the `function` pattern keyword.
  std::shared_ptr<const texture::ValuePattern> parse_function_pattern(const Token& keyword);
  /// The block after `function {` when it is `pigment`, `pattern`, `spline` or `transform`
  /// (vector_functions.cpp); `kind` has been read.
  std::shared_ptr<const function::Function> parse_block_function(const Token& kind);
  /// `(args)` after the name of a declared function, in an ordinary expression.
  Numeric call_function(const Token& name, const function::Function& f);

  // ---- materials (materials.cpp) ----
  std::shared_ptr<const material::Pigment> parse_pigment_block(
      const std::shared_ptr<const material::Pigment>& base);
  material::Finish parse_finish_block(const material::Finish& base);
  /// `subsurface { translucency <c> | material "name" | samples N, M }` inside a finish (sdl/subsurface.cpp).
  void parse_finish_subsurface(material::Finish& f);
  /// `subsurface { samples N, M  radiosity bool }` in global_settings.
  void parse_global_subsurface();
  std::shared_ptr<const material::Interior> parse_interior_block();
  std::shared_ptr<const material::Texture> parse_texture_block();
  /// The inside of a texture block up to `closer` ("}", or "]" for a texture_map entry).
  std::shared_ptr<const material::Texture> parse_texture_body(const char* closer);
  // Patterned textures (texture_maps.cpp).
  struct TexturePatternBuilder;
  /// A pattern, texture_map or pattern modifier inside a texture block, when one is next.
  bool parse_texture_pattern(TexturePatternBuilder& builder);
  /// Makes `texture` the patterned texture the builder describes.
  void finish_texture_pattern(const TexturePatternBuilder& builder, material::Texture& texture,
                              const scene::SourceLocation& where);
  /// One texture block and any `texture {..}` blocks after it, layered (the last on top).
  std::shared_ptr<const material::Texture> parse_layered_textures();
  std::shared_ptr<const material::Material> parse_material_block();
  void parse_reflection(material::Finish& finish);
  /// snell's `blur A` or `samples N` inside reflection/transmission when `word` is one (rough_finish.cpp).
  bool parse_rough_item(const std::string& word, double& blur, int& samples);
  /// snell's `transmission { blur A samples N }` in a finish (rough_finish.cpp).
  void parse_transmission(material::Finish& finish);
  /// `translate v`, `rotate v`, `scale v`, `matrix <..>`, `transform {..}` when one is next.
  std::optional<math::Transform> parse_transform_item();
  math::Transform parse_transform_block();

  // ---- pattern pigments and maps (pigments.cpp) ----
  struct PigmentBuilder;
  /// The inside of a pigment block up to `closer` ("}" for `pigment {`, "]" for a pigment_map entry).
  void parse_pigment_body(PigmentBuilder& builder, const char* closer);
  /// A pattern keyword and its arguments (block pattern entries, gradient's vector) when one is next.
  bool parse_pattern_type(PigmentBuilder& builder);
  /// A pattern modifier (map, wave, turbulence, transform, brick size...) when one is next.
  bool parse_pattern_modifier(PigmentBuilder& builder);
  /// The block after `warp` (warps.cpp).
  void parse_warp(PigmentBuilder& builder);
  /// `{ [type] "file" modifiers }` after `image_map` (image_maps.cpp).
  /// In a `bump_map`, `bump_size` (when given) takes its `bump_size`.
  std::shared_ptr<const material::Pigment> parse_image_map(double* bump_size = nullptr);
  /// An image file named in the scene: next to the scene, then in the library paths; else an error.
  std::filesystem::path find_image_file(const Token& file_token, const std::string& file);
  /// `material_map { ... }` after its keyword (sdl/material_map.cpp).
  std::shared_ptr<const material::TextureSelector> parse_material_map();
  /// `<d>` or `{ <d> [, lo, hi] [altitude <a> [, lo, hi]] }` after `slope`.
  std::shared_ptr<const texture::ValuePattern> parse_slope();
  /// `noise_generator N` after its keyword: 1, 2 or 3, else an error.
  texture::NoiseGenerator parse_noise_generator();
  /// After `magnet`: the type, mandel or julia and julia's constant (pigments.cpp).
  void parse_magnet_head(PigmentBuilder& b);
  /// `{ [IDENT] [v colour] ... }` after `color_map`.
  std::shared_ptr<const texture::ColorMap> parse_color_map();
  /// `{ [IDENT] [v pigment-body] ... }` after `pigment_map`.
  /// `average` maps may leave out an entry's value, which is then a weight of 1 (POV-Ray 3.7).
  std::shared_ptr<const texture::PigmentMap> parse_pigment_map(bool average = false);
  /// A map entry's value after `[`: optional (1) in an `average` map.
  double parse_map_entry_value(bool average);

  // ---- normals (normals.cpp) ----
  struct NormalBuilder;
  /// `{ ... }` after `normal`; null when the block names no pattern (`normal {}`).
  std::shared_ptr<const material::Normal> parse_normal_block();
  /// The inside of a normal block up to `closer` ("}", or "]" for a normal_map entry).
  void parse_normal_body(NormalBuilder& builder, const char* closer);
  /// `slope_map {..}` or `normal_map {..}` after its keyword, into the builder.
  void parse_slope_map(NormalBuilder& builder);
  void parse_normal_map(NormalBuilder& builder);

  // ---- objects (objects.cpp) ----
  std::optional<ParsedObject> parse_object_if_any();
  ParsedObject parse_object(const Token& keyword);
  ParsedObject parse_shape(const Token& keyword);
  ParsedObject parse_union(const Token& keyword);
  ParsedObject parse_blob(const Token& keyword);
  ParsedObject parse_mesh(const Token& keyword);
  /// `mesh { "file" modifiers }` after `mesh {` (mesh_file.cpp; the model is read through Assimp).
  ParsedObject parse_mesh_file(const Token& keyword);
  // ---- mesh2 (mesh2.cpp) ----
  ParsedObject parse_mesh2(const Token& keyword);
  int parse_mesh2_count(const char* list);
  void end_mesh2_list(const char* list, int count, size_t read);
  std::vector<std::array<int, 3>> parse_mesh2_indices(const char* list, size_t limit,
                                                      std::vector<int>* textures);
  // ---- poly, polygon, prism, lathe, sor, text (outline_shapes.cpp) ----
  /// The shape's parameters after `keyword {`, up to its modifiers.
  std::shared_ptr<const geometry::Shape> parse_outline_shape(const Token& keyword);
  int parse_point_count(const char* what, int fewest);
  std::vector<math::Vec2> parse_points_2d(int count);
  void skip_sturm();
  ParsedObject parse_light(const Token& keyword);
  // procedural_objects.cpp, height_field.cpp
  ParsedObject parse_isosurface(const Token& keyword);
  ParsedObject parse_superellipsoid(const Token& keyword);
  // curved_shapes.cpp
  ParsedObject parse_ovus(const Token& keyword);
  ParsedObject parse_lemon(const Token& keyword);
  ParsedObject parse_parametric(const Token& keyword);
  /// `{ box {..} | sphere {..} }` after `contained_by` (isosurface, parametric).
  std::shared_ptr<const geometry::Shape> parse_contained_by();
  ParsedObject parse_height_field(const Token& keyword);
  /// terrain_block.cpp: reads `diamond_square { }`, `fbm { }`... into `grid`; false when none is next.
  bool parse_terrain_if_any(geometry::HeightGrid& grid);
  ParsedObject parse_bicubic_patch(const Token& keyword);
  ParsedObject parse_julia_fractal(const Token& keyword);
  ParsedObject parse_lsystem(const Token& keyword);  // lsystem_block.cpp
  // procedural blocks, snell extensions (particles_block.cpp, boids_block.cpp)
  ParsedObject parse_particle_system(const Token& keyword);
  void parse_particle_emitter(procedural::Emitter& emitter);
  /// `mean +/- variance` (the variance optional, 0 when absent).
  std::pair<double, double> parse_mean_variance();
  ParsedObject parse_boids(const Token& keyword);
  /// `{ objects }` after `context`: the scene objects they become, for a generator's ray queries.
  procedural::ObjectProbe parse_probe_objects(const char* context);
  /// Sets o.shape from `make` (whose exceptions become errors at `keyword`), then reads the modifiers.
  ParsedObject finish_shape(ParsedObject o, const Token& keyword,
                            const std::function<std::shared_ptr<const geometry::Shape>()>& make);
  void parse_object_modifiers(ParsedObject& object);
  bool parse_object_modifier(ParsedObject& object);
  /// clipped_by { ... } / bounded_by { ... } after its keyword.
  void parse_clip_block(ParsedObject& object, const Token& keyword);
  /// motion { ... } and the camera's shutter { ... } after their keyword (motion_blocks.cpp).
  void parse_motion_block(ParsedObject& object, const Token& keyword);
  void parse_shutter_block(scene::CameraSpec& camera, const Token& keyword);
  /// Adds `added`'s nodes to `nodes`, failing past ParseOptions::max_objects.
  void count_objects(long long& nodes, const ParsedObject& added, const scene::SourceLocation& where);
  void attach_pigment(ParsedObject& object, std::shared_ptr<const material::Pigment> pigment);

  // ---- scene items (scene_items.cpp) ----
  void parse_scene_items();
  scene::CameraSpec parse_camera(const scene::CameraSpec& base);
  /// `{ ... }` after `mesh_camera` (mesh_camera_block.cpp).
  void parse_mesh_camera(scene::CameraSpec& cam, const Token& keyword);
  void parse_global_settings();
  /// `{ ... }` after global_settings' `radiosity` (radiosity_block.cpp).
  scene::RadiositySettings parse_radiosity_block();
  /// `{ ... }` after `photons` in global_settings, an object and a light_source (photons_block.cpp).
  scene::PhotonSettings parse_global_photons();
  void parse_object_photons(scene::ObjectPhotons& photons);
  void parse_light_photons(scene::LightPhotons& photons);
  /// `{ keyword ... }`: calls `keyword` with each identifier (already read) until the closing brace.
  void parse_keyword_block(const char* context, const std::function<void(const Token&)>& keyword);
  void parse_background();

  // ---- fog, media, density (atmosphere.cpp) ----
  /// `{ ... }` after `fog`, `media`, `density` or `sky_sphere` (its keyword `word`), as a declarable value.
  Value parse_atmospheric_value(const Token& word);
  scene::Fog parse_fog_block();
  /// Null when the media (or density) uses a pattern snell does not support yet: it is then ignored, with
  /// a warning, as POV-Ray scenes mostly stay readable without it.
  std::optional<material::Media> parse_media_block();
  std::optional<material::Density> parse_density_block();
  scene::SkySphere parse_sky_sphere_block();
  scene::Scene finish_scene();

  ParseOptions options_;
  SourceTexts texts_;
  std::map<std::string, std::shared_ptr<const std::vector<Token>>> token_cache_;
  std::vector<Frame> frames_;
  std::vector<Cond> conds_;
  std::vector<ForLoop> for_loops_;
  /// Values of array elements read through inject_array_element, under names no identifier can have.
  std::map<std::string, Value> element_values_;
  unsigned element_counter_ = 0;
  /// `seed(n)` streams (the generator state of each), indexed by the float `seed` returns.
  std::vector<uint32_t> random_streams_;
  std::vector<std::map<std::string, Value>> scopes_;
  std::map<std::string, UserFile> user_files_;
  size_t bytes_written_ = 0;
  static constexpr size_t kMaxBytesWritten = size_t{256} << 20;
  int macro_depth_ = 0;
  long long tokens_read_ = 0;
  /// Depth of recursive descent (expressions, objects, pigments, textures): hostile input such as 100000
  /// opening parentheses or 5000 nested unions gives a ParseError instead of a stack overflow.
  int nesting_ = 0;
  static constexpr int kMaxNesting = 256;
  class NestingGuard {
   public:
    NestingGuard(Parser& parser, const scene::SourceLocation& where) : parser_(parser) {
      if (++parser_.nesting_ > kMaxNesting) {
        --parser_.nesting_;
        parser_.fail(where, "nested more than " + std::to_string(kMaxNesting) + " levels deep");
      }
    }
    ~NestingGuard() { --parser_.nesting_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

   private:
    Parser& parser_;
  };
  double version_ = 3.7;
  bool in_vector_ = false;
  bool assumed_gamma_seen_ = false;
  /// global_settings' noise_generator, shared with every pattern that names none (povray_noise.hpp).
  std::shared_ptr<texture::NoiseGenerator> global_noise_generator_ =
      std::make_shared<texture::NoiseGenerator>(texture::kDefaultNoiseGenerator);
  scene::Scene scene_;
  /// What `#default {}` has made of POV-Ray's default texture; objects parsed later start from it.
  std::shared_ptr<const material::Texture> default_texture_ = material::Texture::default_texture();
};

}  // namespace snell::sdl
