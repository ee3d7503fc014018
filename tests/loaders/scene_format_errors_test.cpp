// The .scene loader: every error names the line and column and says what was expected.
#include <doctest/doctest.h>

#include "loaders/scene_format_test_support.h"
#include "scene_format/scene_format_syntax.h"

using namespace radiant;

struct ErrorCase {
  const char* text;
  const char* message;
};

static void check_errors(const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& error : cases) {
    std::string text = error.text;  // a std::string so that a failure prints the scene text
    CAPTURE(text);
    CHECK(test::scene_text_error(text) == std::string(error.message));
  }
}

TEST_CASE("syntax errors: stray attributes, bare '@', a late scene line, unknown blocks") {
  check_errors({
      {"p 0 0 0\n", "t.scene:1:1: attribute 'p' outside a block (expected a '@block' header first)"},
      {"# c\n  @ sphere\n", "t.scene:2:3: expected a block name after '@'"},
      {"scene a\nscene b\n", "t.scene:2:1: the 'scene' line must be the first line of the file"},
      {"@sphere\nr 1\np 0 0 0\n @box\n",
       "t.scene:4:2: unknown block '@box' (expected @viewer, @camera, @light, @material, @sphere, @wall, @plane, "
       "@triangle, @polygon, @cylinder, @tube, @mesh, @line, @points, @render)"},
      {"@sphere big\nr 1\np 0 0 0\n", "t.scene:1:9: unexpected 'big' after '@sphere' (this block takes no name)"},
      {"@camera a b\n", "t.scene:1:11: unexpected 'b' after '@camera'"},
  });
}

TEST_CASE("attribute errors: unknown, duplicate (also through an alias), missing") {
  check_errors({
      {"@viewer\np 0 0 0\nf 0 0 -1\nq 1\n", "t.scene:4:1: unknown attribute 'q' in @viewer (expected p, f)"},
      {"@sphere\nr 1\np 0 0 0\n  r 2\n", "t.scene:4:3: duplicate attribute 'r' (already given at line 2)"},
      {"@sphere\nr 1\np 0 0 0\nradius 2\n",
       "t.scene:4:1: duplicate attribute 'radius' (already given at line 2 as 'r')"},
      {"\n@sphere\np 0 0 0\n", "t.scene:2:1: missing required attribute 'radius' (or 'r') in @sphere"},
      {"@tube\npoint 0 0 0\nradius 1\n", "t.scene:1:1: missing required attribute 'axis' in @tube"},
      {"@viewer\np 0 0 0\n", "t.scene:1:1: missing required attribute 'f' in @viewer"},
      {"@light point\ndirection 0 0 1\n",
       "t.scene:2:1: unknown attribute 'direction' in @light point (expected color, position, attenuation)"},
  });
}

TEST_CASE("number errors: not a number, NaN, infinity, out of range, wrong count") {
  check_errors({
      {"@sphere\nr 1\np 0 abc 0\n", "t.scene:3:5: expected a number, got 'abc'"},
      {"@sphere\nr 1\np 0 1.5x 0\n", "t.scene:3:5: expected a number, got '1.5x'"},
      {"@sphere\nr 1\np 0 0 nan\n", "t.scene:3:7: expected a finite number, got 'nan'"},
      {"@sphere\nr -inf\np 0 0 0\n", "t.scene:2:3: expected a finite number, got '-inf'"},
      {"@sphere\nr 1\np 1e39 0 0\n", "t.scene:3:3: number '1e39' is out of range"},
      {"@sphere\nr 1\np 1e999 0 0\n", "t.scene:3:3: number '1e999' is out of range"},
      {"@sphere\nr 1\np 0 0\n", "t.scene:3:1: 'p' expects 3 numbers, got 2"},
      {"@sphere\nr 1 2\np 0 0 0\n", "t.scene:2:1: 'r' expects 1 number, got 2"},
      {"@sphere\nr 1\np 0 0 0\nkd 0.5 0.5\n", "t.scene:4:1: 'kd' expects 1 or 3 numbers, got 2"},
      {"@sphere\nr 1\np 0 0 0\nkd\n", "t.scene:4:1: 'kd' expects 1 or 3 numbers, got 0"},
      {"@polygon\nvertices\n", "t.scene:2:1: 'vertices' expects numbers, got none"},
  });
}

TEST_CASE("range errors: zero or negative radius, negative colors, zero-length directions") {
  check_errors({
      {"@sphere\nr 0\np 0 0 0\n", "t.scene:2:3: 'r' must be positive, got 0"},
      {"@sphere\nradius -2\np 0 0 0\n", "t.scene:2:8: 'radius' must be positive, got -2"},
      {"@sphere\nr 1\np 0 0 0\ne -1\n", "t.scene:4:3: 'e' must not be negative, got -1"},
      {"@sphere\nr 1\np 0 0 0\nc 10 -20 30\n", "t.scene:4:6: 'c' must not be negative, got -20"},
      {"@wall\np 0 0 0\nn 0 0 0\n", "t.scene:3:1: 'n' must not be zero-length"},
      {"@viewer\np 0 0 0\nf 0 0 0\n", "t.scene:3:1: 'f' must not be zero-length"},
      {"@light directional\ndirection 0 0 0\n", "t.scene:2:1: 'direction' must not be zero-length"},
      {"@material m\nshininess -1\n", "t.scene:2:11: 'shininess' must not be negative, got -1"},
      {"@material m\nior 0\n", "t.scene:2:5: 'ior' must be positive, got 0"},
  });
}

TEST_CASE("word errors: bad boolean, unknown choice, wrong word count") {
  check_errors({
      {"@sphere\nr 1\np 0 0 0\ns yes\n", "t.scene:4:3: expected true or false, got 'yes'"},
      {"@sphere\nr 1\np 0 0 0\ns\n", "t.scene:4:1: 's' expects 1 word, got 0"},
      {"@render\nmode fast\n", "t.scene:2:6: unknown mode 'fast' (expected auto, whitted, path or naive)"},
      {"@render\nsampler halton\n",
       "t.scene:2:9: unknown sampler 'halton' (expected grid, random, jittered or sobol)"},
      {"@render\nspp 2.5\n", "t.scene:2:5: expected a whole number, got '2.5'"},
      {"@render\nspp 0\n", "t.scene:2:5: 'spp' must be between 1 and 1048576, got 0"},
      {"@render\nwidth 99999999999\n", "t.scene:2:7: 'width' must be between 1 and 65536, got 99999999999"},
      {"@render\nbackground 1 2\n", "t.scene:2:1: 'background' expects 1 or 3 numbers, got 2"},
  });
}

TEST_CASE("material errors: names, unknown references, mixing the older and the new style") {
  check_errors({
      {"@material\nkd 1\n", "t.scene:1:1: expected a material name after '@material'"},
      {"@material a\n@material a\n", "t.scene:2:11: material 'a' is already defined"},
      {"@material a\nc 255 0 0\n",
       "t.scene:2:1: unknown attribute 'c' in @material (expected kd, ks, ka, kr, kt, shininess, ior, emission)"},
      {"@sphere\nr 1\np 0 0 0\nmaterial glass\n",
       "t.scene:4:10: unknown material 'glass' (define it with '@material glass' before this line)"},
      {"@sphere\nr 1\np 0 0 0\nmaterial a b\n", "t.scene:4:1: 'material' expects 1 word, got 2"},
      {"@sphere\nr 1\np 0 0 0\nc 255 0 0\nkd 0.5\n",
       "t.scene:4:1: older-format 'c' cannot be combined with 'kd' on one shape"},
      {"@sphere\nr 1\np 0 0 0\nc 300 0 0\n", "t.scene:4:3: 'c' is a colour from 0 to 255, got 300"},
      {"@sphere\nr 1\np 0 0 0\nc 0 0 255.5\n", "t.scene:4:7: 'c' is a colour from 0 to 255, got 255.5"},
      {"@sphere\nr 1\np 0 0 0\nc 256\n", "t.scene:4:3: 'c' is a colour from 0 to 255, got 256"},
  });
}

TEST_CASE("camera errors: up parallel to the view, conflicting or missing attributes, ranges") {
  check_errors({
      {"@camera\nposition 0 0 0\ndirection 0 1 0\nup 0 2 0\n", "t.scene:4:1: 'up' is parallel to the view direction"},
      {"@camera\nposition 0 0 0\nlook-at 0 -5 0\nup 0 1 0\n", "t.scene:4:1: 'up' is parallel to the view direction"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nlook-at 0 0 -1\n",
       "t.scene:4:1: 'look-at' cannot be combined with 'direction'"},
      {"@camera\nposition 0 0 0\n", "t.scene:1:1: missing required attribute 'direction' or 'look-at' in @camera"},
      {"@camera\ndirection 0 0 -1\n", "t.scene:1:1: missing required attribute 'position' in @camera"},
      {"@camera\nposition 1 1 1\nlook-at 1 1 1\n", "t.scene:3:1: 'look-at' must differ from 'position'"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nfov 180\n",
       "t.scene:4:5: 'fov' must be between 0 and 180 degrees, got 180"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nfov 40\nview-size 2 2\n",
       "t.scene:5:1: 'view-size' cannot be combined with 'fov'"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nview-distance 2\n",
       "t.scene:1:1: missing required attribute 'view-size' in @camera"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nview-distance 2\nview-size 2\n",
       "t.scene:5:1: 'view-size' expects 2 numbers (width height), got 1"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nview-distance 2\nview-size 2 0\n",
       "t.scene:5:1: 'view-size' must be positive"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nfov 40\northographic 2\n",
       "t.scene:5:1: 'orthographic' cannot be combined with 'fov'"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\nresolution 640 0\n",
       "t.scene:4:16: 'resolution' must be between 1 and 65536, got 0"},
  });
}

TEST_CASE("light errors: type, attenuation") {
  check_errors({
      {"@light\n", "t.scene:1:1: expected a light type after '@light' (ambient, directional, point or spot)"},
      {"@light area\n", "t.scene:1:8: unknown light type 'area' (expected ambient, directional, point or spot)"},
      {"@light spot\nposition 0 0 0\n", "t.scene:1:1: missing required attribute 'direction' in @light spot"},
      {"@light point\nposition 0 0 0\nattenuation 1 -1 0\n",
       "t.scene:3:15: 'attenuation' must not be negative, got -1"},
      {"@light point\nposition 0 0 0\nattenuation 0 0 0\n", "t.scene:3:1: 'attenuation' must not be all zero"},
      {"@light point\nposition 0 0 0\nattenuation 1 0\n",
       "t.scene:3:1: 'attenuation' expects 3 numbers (kc kl kq), got 2"},
  });
}

TEST_CASE("cylinder errors: mixed forms, equal end points") {
  check_errors({
      {"@cylinder\nfrom 0 0 0\nto 0 1 0\nheight 2\nradius 1\n",
       "t.scene:4:1: 'height' cannot be combined with 'from' and 'to'"},
      {"@cylinder\nfrom 0 1 0\nto 0 1 0\nradius 1\n", "t.scene:3:1: 'to' must differ from 'from'"},
      {"@cylinder\nto 0 1 0\nradius 1\n", "t.scene:1:1: missing required attribute 'from' in @cylinder"},
      {"@cylinder\nbase 0 0 0\naxis 0 1 0\nheight 0\nradius 1\n", "t.scene:4:8: 'height' must be positive, got 0"},
  });
}

TEST_CASE("polygon errors: vertex counts, non-planar, self-crossing, degenerate") {
  check_errors({
      {"@triangle\nvertices 0 0 0 1 0 0\n", "t.scene:2:1: 'vertices' expects at least 3 vertices, got 2"},
      {"@triangle\nvertices 0 0 0 1 0 0 0 1\n", "t.scene:2:1: 'vertices' expects 3 numbers per vertex, got 8 numbers"},
      {"@triangle\nvertices 0 0 0 1 0 0 0 1 0 1 1 0\n", "t.scene:2:1: 'vertices' of @triangle expects 9 numbers, got 12"},
      {"@triangle\nvertices 0 0 0 1 1 1 2 2 2\n", "t.scene:2:1: triangle has zero area (its vertices are collinear)"},
      {"@polygon\n  vertices 0 0 0  1 0 0  1 1 0.5  0 1 0\n",
       "t.scene:2:3: polygon is not planar (vertex 1 is 0.118 away from the mean plane)"},
      {"@polygon\nvertices 0 0 0  3 3 0  3 0 0  0 1 0\n",
       "t.scene:2:1: polygon crosses itself (its edges cross or it winds around twice)"},
  });
}

TEST_CASE("mesh errors: transform attributes") {
  check_errors({
      {"@mesh\ntranslate 0 0 0\n", "t.scene:1:1: missing required attribute 'file' in @mesh"},
      {"@mesh\nfile a.obj\nscale 1 0 1\n", "t.scene:3:9: 'scale' must not be zero"},
      {"@mesh\nfile a.obj\nrotate 0 0 0 90\n", "t.scene:3:1: 'rotate' axis must not be zero-length"},
      {"@mesh\nfile a.obj\nrotate 0 1 0\n", "t.scene:3:1: 'rotate' expects 4 numbers (axis x y z, degrees), got 3"},
      {"@mesh\nfile a.obj\nmatrix 1 0 0\n", "t.scene:3:1: 'matrix' expects 12 or 16 numbers (row-major), got 3"},
      {"@mesh\nfile a.obj\nmatrix 1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1\n",
       "t.scene:3:1: 'matrix' must be affine (last row 0 0 0 1)"},
      {"@mesh\nfile a.obj\nmatrix 1 0 0 0 0 1 0 0 0 0 0 0\n", "t.scene:3:1: 'matrix' is singular"},
      {"@mesh\nfile a.obj\nmatrix 1.00000012 1 0 0 1 0.99999994 0 0 0 0 1 0\n",
       "t.scene:3:1: 'matrix' is too close to singular to invert in single precision, as ray tracing must"},
      {"@mesh\nfile a.obj\nmatrix 1 0 0 0 0 1 0 0 0 0 1 0\ntranslate 1 2 3\n",
       "t.scene:4:1: 'translate' cannot be combined with 'matrix'"},
  });
}

TEST_CASE("hostile input: an over-long line, more text than the memory limit, control bytes in names") {
  std::string long_line = "# " + std::string(scene_format::max_line_length, 'x') + "\n";
  CHECK(test::scene_text_error("@sphere\n" + long_line) == "t.scene:2:1: line is longer than 1048576 characters");
  LoadOptions small;
  small.max_memory_bytes = 12;
  // The first statement already costs its token, block and attribute, twice for vector growth.
  using namespace scene_format;
  size_t statement = 2 * (sizeof(Block) + sizeof(Attribute) + sizeof(Token));
  CHECK(test::scene_text_error("@sphere\nr 1\np 0 0 0\n", small) ==
        "t.scene:1:1: the scene text: " + std::to_string(statement) +
            " bytes needed, over the memory limit of 12 bytes (--max-memory)");
  CHECK(test::scene_text_error(std::string("@sph\x01re\n", 9)) ==
        "t.scene:1:1: unknown block '@sph?re' (expected @viewer, @camera, @light, @material, @sphere, @wall, "
        "@plane, @triangle, @polygon, @cylinder, @tube, @mesh, @line, @points, @render)");
  CHECK(test::scene_text_error("@sphere\nr 1\np " + std::string(100, '7') + "x 0 0\n") ==
        "t.scene:3:3: expected a number, got '7777777777777777777777777777777777777777...'");
}

TEST_CASE("conflicting attributes are reported at whichever comes later in the file") {
  check_errors({
      {"@camera\nposition 0 0 0\nlook-at 0 0 -1\ndirection 0 0 -1\n",
       "t.scene:4:1: 'direction' cannot be combined with 'look-at'"},
      {"@camera\nposition 0 0 0\ndirection 0 0 -1\northographic 2\nfov 40\n",
       "t.scene:5:1: 'fov' cannot be combined with 'orthographic'"},
  });
}

TEST_CASE("finite inputs whose combination overflows are rejected, not passed on as infinities") {
  check_errors({
      {"@camera\nposition 3e38 0 0\nlook-at -3e38 0 0\n", "t.scene:3:1: 'look-at' is too far from 'position'"},
      {"@cylinder\nfrom 2e38 0 0\nto 0 2e38 0\nradius 1\n", "t.scene:3:1: 'to' is too far from 'from'"},
  });
}
