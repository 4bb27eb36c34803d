// SPDX-License-Identifier: MIT
// image_io.h implemented with OpenImageIO. Every entry point catches all
// exceptions: they must never unwind into the C callers.
#include "image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

using namespace OIIO;

namespace {

const int kMaxChannels = 24; // image::channel_names

void set_error(char *err, size_t size, const std::string &msg)
{
    if (err && size)
        std::snprintf(err, size, "%s", msg.c_str());
}

std::string extension_of(const char *path)
{
    const char *dot = std::strrchr(path, '.');
    const char *slash = std::strrchr(path, '/');
    std::string ext = (dot && (!slash || dot > slash)) ? dot + 1 : "";
    for (char &c : ext)
        c = (char)std::tolower((unsigned char)c);
    return ext;
}

float linear_to_srgb(float x)
{
    if (!(x > 0))
        return 0;
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1 / 2.4f) - 0.055f;
}

// Geometry AOVs need full precision; colour and visibility are fine as half.
bool wants_float(const std::string &name)
{
    return name.compare(0, 2, "P.") == 0 || name.compare(0, 2, "N.") == 0 || name == "Z";
}

// Writes all of bytes to path and makes sure they reached the file system:
// a full disk shows up here (write, flush or close), not as a short file.
// (No fsync: file systems that reserve space at write() report it there.)
bool write_bytes(const std::string &path, const std::vector<unsigned char> &bytes, std::string &why)
{
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) {
        why = std::string("cannot create: ") + std::strerror(errno);
        return false;
    }
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0;
    int saved = errno;
    if (std::fclose(f) != 0 && ok) {
        ok = false;
        saved = errno;
    }
    if (!ok)
        why = std::string("write failed: ") + std::strerror(saved);
    return ok;
}

// Encodes through an OIIO ImageOutput of format `ext` into memory, then
// writes `tmp` with checked I/O: OIIO's PNG writer reports no write errors,
// so on a full disk it would leave a truncated file and say nothing.
bool write_spec(const std::string &ext, const std::string &tmp, const ImageSpec &spec,
                TypeDesc data_type, const void *data, std::string &why)
{
    auto out = ImageOutput::create(ext);
    if (!out) {
        why = "no writer for ." + ext + ": " + OIIO::geterror();
        return false;
    }
    if (!out->supports("ioproxy")) {
        why = "the ." + ext + " writer cannot encode into memory";
        return false;
    }
    std::vector<unsigned char> bytes;
    Filesystem::IOVecOutput memory(bytes);
    Filesystem::IOProxy *proxy = &memory;
    ImageSpec to_memory = spec;
    to_memory.attribute("oiio:ioproxy", TypeDesc::PTR, &proxy);
    if (!out->open(tmp, to_memory) || !out->write_image(data_type, data) || !out->close() ||
        out->has_error()) {
        why = out->geterror();
        return false;
    }
    return write_bytes(tmp, bytes, why);
}

bool write_exr(const std::string &tmp, const image *img, std::string &why)
{
    ImageSpec spec(img->width, img->height, img->channels, TypeDesc::HALF);
    spec.alpha_channel = spec.z_channel = -1;
    spec.channelformats.assign((size_t)img->channels, TypeDesc::HALF);
    for (int c = 0; c < img->channels; c++) {
        if (img->channel_names[c][0])
            spec.channelnames[(size_t)c] = img->channel_names[c];
        const std::string &name = spec.channelnames[(size_t)c];
        if (wants_float(name))
            spec.channelformats[(size_t)c] = TypeDesc::FLOAT;
        if (name == "A")
            spec.alpha_channel = c;
        if (name == "Z")
            spec.z_channel = c;
    }
    spec.attribute("compression", "zip");
    return write_spec("exr", tmp, spec, TypeDesc::FLOAT, img->pixels, why);
}

// R, G, B (+ A) by name when present, else the first channels (up to four).
bool write_png(const std::string &tmp, const image *img, int srgb, std::string &why)
{
    int sel[4], n = 0;
    const int r = image_channel(img, "R"), g = image_channel(img, "G"), b = image_channel(img, "B");
    if (r >= 0 && g >= 0 && b >= 0) {
        sel[n++] = r;
        sel[n++] = g;
        sel[n++] = b;
        if (image_channel(img, "A") >= 0)
            sel[n++] = image_channel(img, "A");
    } else {
        for (n = 0; n < img->channels && n < 4; n++)
            sel[n] = n;
    }
    const int alpha = (n == 2 || n == 4) ? n - 1 : -1;
    const size_t pixels = (size_t)img->width * (size_t)img->height;
    std::vector<uint8_t> bytes(pixels * (size_t)n);
    for (size_t p = 0; p < pixels; p++)
        for (int c = 0; c < n; c++) {
            float v = img->pixels[p * (size_t)img->channels + (size_t)sel[c]];
            if (srgb && c != alpha)
                v = linear_to_srgb(v);
            v = v > 0 ? (v < 1 ? v : 1) : 0; // also maps NaN to 0
            bytes[p * (size_t)n + (size_t)c] = (uint8_t)std::lround(v * 255.0f);
        }
    ImageSpec spec(img->width, img->height, n, TypeDesc::UINT8);
    spec.alpha_channel = alpha;
    // Our colour is not premultiplied: stop OIIO from dividing it by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    return write_spec("png", tmp, spec, TypeDesc::UINT8, bytes.data(), why);
}

// Unique sibling name, so rename() stays on one file system.
std::string temp_name(const char *path)
{
    static std::atomic<unsigned> counter{ 0 };
    char suffix[48];
    std::snprintf(suffix, sizeof suffix, ".tmp-%ld-%u", (long)getpid(), counter++);
    return std::string(path) + suffix;
}

bool split_names(const char *list, std::vector<std::string> &names)
{
    std::string cur;
    for (const char *c = list;; c++) {
        if (*c == ',' || *c == '\0') {
            if (cur.empty())
                return false;
            names.push_back(cur);
            cur.clear();
            if (!*c)
                return true;
        } else if (*c != ' ') {
            cur += *c;
        }
    }
}

} // namespace

extern "C" int image_write(const char *path, const image *img, int srgb, char *err, size_t err_size)
{
    std::string tmp;
    try {
        if (!img->pixels || img->width <= 0 || img->height <= 0 || img->channels <= 0 ||
            img->channels > kMaxChannels) {
            set_error(err, err_size, std::string(path) + ": empty or invalid image");
            return 0;
        }
        const std::string ext = extension_of(path);
        if (ext != "exr" && ext != "png") {
            set_error(err, err_size, std::string(path) + ": unsupported extension (use .exr or .png)");
            return 0;
        }
        tmp = temp_name(path);
        std::string why;
        bool ok = ext == "exr" ? write_exr(tmp, img, why) : write_png(tmp, img, srgb, why);
        if (ok && std::rename(tmp.c_str(), path) != 0) {
            why = std::string("cannot rename the temporary file: ") + std::strerror(errno);
            ok = false;
        }
        if (!ok) {
            std::remove(tmp.c_str());
            set_error(err, err_size, std::string(path) + ": " + why);
            return 0;
        }
        return 1;
    } catch (const std::exception &e) {
        if (!tmp.empty())
            std::remove(tmp.c_str());
        set_error(err, err_size, std::string(path) + ": " + e.what());
    } catch (...) {
        if (!tmp.empty())
            std::remove(tmp.c_str());
        set_error(err, err_size, std::string(path) + ": unknown exception");
    }
    return 0;
}

namespace {

// Reads `name` through OpenImageIO, from `proxy` when it is not null (the
// name then only picks the format by its extension).
int read_image(const std::string &name, Filesystem::IOProxy *proxy, image *img, char *err,
               size_t err_size)
{
    std::memset(img, 0, sizeof *img);
    try {
        // Return pixels as stored: no premultiplying by alpha on read.
        ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        if (proxy) // the readers take it from the configuration
            config.attribute("oiio:ioproxy", TypeDesc::PTR, &proxy);
        auto in = ImageInput::open(name, &config, proxy);
        if (!in) {
            set_error(err, err_size, name + ": " + OIIO::geterror());
            return 0;
        }
        const ImageSpec &spec = in->spec();
        if (spec.deep || spec.depth > 1 || spec.nchannels > kMaxChannels) {
            set_error(err, err_size, name + ": deep, volume or more than 24 channels");
            return 0;
        }
        for (int c = 0; c < spec.nchannels; c++)
            if (spec.channel_name(c).size() >= sizeof img->channel_names[0]) {
                set_error(err, err_size, name + ": channel name too long: " +
                                             std::string(spec.channel_name(c)));
                return 0;
            }
        if (!image_alloc(img, spec.width, spec.height, spec.nchannels)) {
            set_error(err, err_size, name + ": image too large or empty");
            return 0;
        }
        for (int c = 0; c < spec.nchannels; c++)
            std::snprintf(img->channel_names[c], sizeof img->channel_names[c], "%s",
                          std::string(spec.channel_name(c)).c_str());
        if (!in->read_image(0, 0, 0, spec.nchannels, TypeDesc::FLOAT, img->pixels)) {
            set_error(err, err_size, name + ": " + in->geterror());
            image_free(img);
            return 0;
        }
        in->close();
        return 1;
    } catch (const std::exception &e) {
        set_error(err, err_size, name + ": " + e.what());
    } catch (...) {
        set_error(err, err_size, name + ": unknown exception");
    }
    image_free(img);
    return 0;
}

} // namespace

extern "C" int image_read(const char *path, image *img, char *err, size_t err_size)
{
    return read_image(path, nullptr, img, err, err_size);
}

extern "C" int image_read_memory(const void *data, size_t size, const char *format_hint, image *img,
                                 char *err, size_t err_size)
{
    const unsigned char *b = (const unsigned char *)data;
    std::string ext;
    std::memset(img, 0, sizeof *img);
    try {
        for (const char *c = format_hint ? format_hint : ""; *c && ext.size() < 8; c++)
            if (std::isalnum((unsigned char)*c))
                ext += (char)std::tolower((unsigned char)*c);
        // No hint: the signature decides (PNG, JPEG are what glTF allows).
        if (ext.empty() && size >= 4 && std::memcmp(b, "\x89PNG", 4) == 0)
            ext = "png";
        if (ext.empty() && size >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF)
            ext = "jpg";
        if (ext.empty()) {
            set_error(err, err_size, "embedded image of unknown format");
            return 0;
        }
        Filesystem::IOMemReader memory(data, size);
        return read_image("embedded." + ext, &memory, img, err, err_size);
    } catch (...) {
        set_error(err, err_size, "embedded image: cannot decode");
    }
    return 0;
}

extern "C" int image_compare(const image *a, const image *b, const char *channels, const float *mask,
                             double threshold, image_diff *out)
{
    try {
        std::memset(out, 0, sizeof *out);
        if (!a->pixels || !b->pixels || a->width != b->width || a->height != b->height)
            return 0;
        std::vector<std::string> names;
        if (channels && channels[0]) {
            if (!split_names(channels, names))
                return 0;
        } else {
            for (int c = 0; c < a->channels; c++)
                names.push_back(a->channel_names[c]);
        }
        std::vector<int> ia, ib;
        for (const std::string &n : names) {
            ia.push_back(image_channel(a, n.c_str()));
            ib.push_back(image_channel(b, n.c_str()));
            if (ia.back() < 0 || ib.back() < 0)
                return 0;
        }
        const int n = (int)names.size();
        // Wrap the callers' pixels (read only), pick the channels, diff.
        ImageBuf wa(ImageSpec(a->width, a->height, a->channels, TypeDesc::FLOAT), a->pixels);
        ImageBuf wb(ImageSpec(b->width, b->height, b->channels, TypeDesc::FLOAT), b->pixels);
        ImageBuf sa = ImageBufAlgo::channels(wa, n, ia);
        ImageBuf sb = ImageBufAlgo::channels(wb, n, ib);
        ImageBuf diff = ImageBufAlgo::absdiff(sa, sb);
        if (diff.has_error())
            return 0;
        const size_t pixels = (size_t)a->width * (size_t)a->height;
        std::vector<float> d(pixels * (size_t)n);
        if (!diff.get_pixels(diff.roi(), TypeDesc::FLOAT, d.data()))
            return 0;
        double sum = 0;
        for (size_t p = 0; p < pixels; p++) {
            if (mask && mask[p] == 0)
                continue;
            bool over = false;
            for (int c = 0; c < n; c++) {
                double v = d[p * (size_t)n + (size_t)c];
                if (std::isnan(v)) // a NaN on one side is as wrong as it gets
                    v = INFINITY;
                sum += v;
                if (v > out->max_abs)
                    out->max_abs = v;
                over = over || v > threshold;
            }
            out->over_threshold += over;
            out->compared++;
        }
        out->mean_abs = out->compared ? sum / ((double)out->compared * n) : 0.0;
        return 1;
    } catch (...) {
        std::memset(out, 0, sizeof *out);
        return 0;
    }
}
