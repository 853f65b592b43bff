#pragma once
// Reads a named output back to CPU memory as raw float values (top-down rows),
// or as the display image the buffer view makes of it. Every resource kind
// reads as one 2D image, laid out as the buffer view shows it (ImageLayout):
// a multisample texture resolved (the mean of its samples) or one sample, an
// array or 3D texture as a grid of layers (or one layer), a cube as an
// unfolded cross, a per-pixel buffer as an image and any other buffer as a table.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "renderer/graph/OutputRegistry.h"

namespace dw {

namespace gl {
class Texture;
}

// Which part of a layered or multisample output to show.
struct ViewSelection {
    int layer = -1;   // arrays, 3D: a layer (slice); cube arrays: a cube; -1: all, in a grid
    int sample = -1;  // multisample: one sample; -1: resolved (the mean of the samples)
};

// How an output is laid out as one image. Coordinates here are GL's (rows
// bottom-up); read-back flips the result to top-down like every other image.
//  - Plain: 2D and multisample textures, per-pixel buffers (element y*width + x,
//    y counted from the bottom as gl_FragCoord counts): the source's own size.
//  - Layers: arrays and 3D textures, one cell per layer (slice).
//  - Crosses: cubes and cube arrays, one cell per cube, each an unfolded cross
//    of 4x3 faces: +Y on top; -X, +Z, +X, -Z in the middle row; -Y below; the
//    other cells empty. Each face shows row t = 0 at its top, as the cube map
//    addresses it, so the edges of neighbouring faces meet.
//  - Table: a buffer that is not per pixel: one row per element (element 0 at
//    the top), one column per 4-byte word of the element.
// Cells are laid out in a grid of ceil(sqrt(cells)) columns, in reading order
// from the top left; cells past the last one are empty (dark in the view, 0 in read-back).
struct ImageLayout {
    enum class Arrangement { Plain = 0, Layers = 1, Crosses = 2, Table = 3 };
    Arrangement arrangement = Arrangement::Plain;
    int cellWidth = 0, cellHeight = 0;  // one layer or face (texels); table: words per element x elements
    int first = 0;                      // the first layer (cube) shown
    int cells = 1, columns = 1;         // the grid
    int width = 0, height = 0;          // the whole image
    int samples = 1;                    // multisample: the texture's samples
    int sample = -1;                    // the sample shown, -1: their mean
    int wordStep = 1;                   // buffers: 4-byte words per step of the element index (per-pixel buffers: per element)
    bool uintWords = false;             // buffers: words read as unsigned integers (Count outputs), else as floats
    bool truncated = false;             // the image would exceed GL_MAX_TEXTURE_SIZE: fewer cells (rows) are shown
    // Maps a pixel of the image to the source: texel (x, y) and layer (array
    // layer, 3D slice, or cube-map layer = 6 x cube + face); for buffers (x, y)
    // index elements (per-pixel) or words in a row (table). False in empty cells.
    bool toSource(int x, int y, glm::ivec3& source) const;
};
ImageLayout imageLayout(const PublishedOutput& output, ViewSelection selection = {});
// The kind of an allocated output, from the GL object (imported outputs included).
ResourceKind resourceKind(const PublishedOutput& output);
// What the layer selection ranges over: layers (arrays, 3D), cubes (cube
// arrays); 0 for kinds without a selectable layer.
int selectableLayers(const PublishedOutput& output);
// Samples of a multisample output; 1 for every other kind.
int sampleCount(const PublishedOutput& output);
// A per-pixel buffer: declared with a frame-relative size.
bool isPerPixelBuffer(const PublishedOutput& output);
// Integer texture formats (R32UI, RGBA8I, ...): read as integers, shown as their values.
bool isUnsignedIntegerFormat(GLenum format);
bool isSignedIntegerFormat(GLenum format);

// An 8-bit colour output that already holds display values (the tone-mapped
// image and what follows it), shown and saved as it is.
bool isDisplayReady(const PublishedOutput& output);
// Raw values: depth as 1 channel, KL normals as 2, colour as 3 or 4; buffers as
// 1 (the first word of each element, or each word of the table).
FloatImage readOutputRaw(const PublishedOutput& output, ViewSelection selection = {});
// Every sample of a multisample texture in a region (GL coordinates): value
// (y * width + x) * samples + s. Runs a small compute shader; blocks.
std::vector<glm::vec4> readSamples(const gl::Texture& texture, int x, int y, int width, int height);
// An RGBA8 texture (e.g. a buffer view) as floats in [0, 1], top-down.
FloatImage readRgba8(const gl::Texture& texture);
// The bound window's back buffer (after UI drawing, before the swap), as RGB.
FloatImage readWindowFramebuffer(int width, int height);
// EXR channel names for an output's raw read-back.
std::vector<std::string> rawChannelNames(const PublishedOutput& output);

}  // namespace dw
