#include "jpeg_decode.h"

// jpeglib.h needs size_t and FILE declared first.
#include <jerror.h>
#include <jpeglib.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>

#include "animkit/trajectory/image_strokes.h"
#include "image_limits.h"

namespace animkit::image_detail {

namespace {

// A crafted progressive JPEG can hold thousands of tiny scans, each a pass over the whole
// coefficient buffer; real files have about ten. More than this is refused as corrupt.
constexpr int kMaxScans = 500;

// libjpeg's error manager with our jump target and the message that stopped decoding. A
// plain struct: libjpeg reports errors by longjmp, which must not skip a destructor.
struct JpegErrors {
  jpeg_error_mgr mgr;  // first, so libjpeg's cinfo->err points at the whole struct
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  bool truncated;  // "Premature end of JPEG file": libjpeg would fill the rest with gray
  bool too_many_scans;
};

JpegErrors* errors_of(j_common_ptr cinfo) {
  return reinterpret_cast<JpegErrors*>(cinfo->err);
}

[[noreturn]] void error_exit(j_common_ptr cinfo) {
  JpegErrors* errors = errors_of(cinfo);
  (*cinfo->err->format_message)(cinfo, errors->message);
  std::longjmp(errors->jump, 1);
}

// libjpeg only warns (msg_level -1) where data is lost: a file that ends early (it then
// invents the rest of the picture), bad Huffman codes, markers in the middle of the data. All
// of those stop the decode; only warnings about metadata that costs no pixels pass.
void emit_message(j_common_ptr cinfo, int msg_level) {
  if (msg_level != -1) return;  // trace messages
  const int code = cinfo->err->msg_code;
  if (code == JWRN_JFIF_MAJOR || code == JWRN_ADOBE_XFORM || code == JWRN_BOGUS_ICC) return;
  JpegErrors* errors = errors_of(cinfo);
  errors->truncated = code == JWRN_JPEG_EOF;
  (*cinfo->err->format_message)(cinfo, errors->message);
  std::longjmp(errors->jump, 1);
}

void output_message(j_common_ptr) {}  // nothing is printed; errors become Result values

void progress_monitor(j_common_ptr cinfo) {
  if (!cinfo->is_decompressor) return;
  if (reinterpret_cast<j_decompress_ptr>(cinfo)->input_scan_number > kMaxScans) {
    errors_of(cinfo)->too_many_scans = true;
    std::longjmp(errors_of(cinfo)->jump, 1);
  }
}

enum class JpegOutcome { decoded, failed, too_large };

// Adobe's CMYK JPEGs store the inks inverted (255 = no ink), other writers do not.
std::uint8_t cmyk_channel(int c, int k, bool inverted) {
  if (!inverted) {
    c = 255 - c;
    k = 255 - k;
  }
  return static_cast<std::uint8_t>((c * k + 127) / 255);
}

// From the header to the end of the image, into `out` as 8-bit RGBA. Nothing in this frame
// has a destructor (see JpegErrors).
JpegOutcome run_libjpeg(jpeg_decompress_struct* cinfo, JpegErrors* errors, jpeg_progress_mgr* progress,
                    std::span<const std::uint8_t> data, Image* out) {
  if (setjmp(errors->jump)) return JpegOutcome::failed;
  jpeg_create_decompress(cinfo);
  cinfo->progress = progress;
  jpeg_mem_src(cinfo, data.data(), static_cast<unsigned long>(data.size()));
  jpeg_read_header(cinfo, TRUE);
  if (cinfo->image_width > JDIMENSION(kMaxImageSide) ||
      cinfo->image_height > JDIMENSION(kMaxImageSide)) {
    return JpegOutcome::too_large;
  }
  const bool cmyk = cinfo->jpeg_color_space == JCS_CMYK || cinfo->jpeg_color_space == JCS_YCCK;
  cinfo->out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
  jpeg_start_decompress(cinfo);
  if (cinfo->output_components != 4) {
    (*cinfo->err->error_exit)(reinterpret_cast<j_common_ptr>(cinfo));  // not reached in practice
  }
  *out = Image(static_cast<int>(cinfo->output_width), static_cast<int>(cinfo->output_height));
  while (cinfo->output_scanline < cinfo->output_height) {
    JSAMPROW row =
        reinterpret_cast<JSAMPROW>(&out->at(0, static_cast<int>(cinfo->output_scanline)));
    jpeg_read_scanlines(cinfo, &row, 1);
  }
  if (cmyk) {
    const bool inverted = cinfo->saw_Adobe_marker;
    for (Pixel& p : out->pixels) {
      const int k = p.a;
      p = {cmyk_channel(p.r, k, inverted), cmyk_channel(p.g, k, inverted),
           cmyk_channel(p.b, k, inverted), 255};
    }
  }
  jpeg_finish_decompress(cinfo);  // reads to EOI, where garbage left in the data shows
  return JpegOutcome::decoded;
}

}  // namespace

Result<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::string_view name) {
  jpeg_decompress_struct cinfo;
  std::memset(&cinfo, 0, sizeof cinfo);
  JpegErrors errors;
  std::memset(&errors, 0, sizeof errors);
  cinfo.err = jpeg_std_error(&errors.mgr);
  errors.mgr.error_exit = error_exit;
  errors.mgr.emit_message = emit_message;
  errors.mgr.output_message = output_message;
  jpeg_progress_mgr progress{};
  progress.progress_monitor = progress_monitor;
  Image image;
  const JpegOutcome outcome = run_libjpeg(&cinfo, &errors, &progress, bytes, &image);
  const JDIMENSION width = cinfo.image_width, height = cinfo.image_height;
  jpeg_destroy_decompress(&cinfo);
  switch (outcome) {
    case JpegOutcome::decoded:
      return image;
    case JpegOutcome::too_large:
      if (auto ok = check_image_side(width, height, name); !ok) return fail(ok.error().message);
      return fail(std::string(name) + ": the image is too large");
    case JpegOutcome::failed:
      break;
  }
  if (errors.too_many_scans) {
    return corrupt(name, "JPEG", "more than " + std::to_string(kMaxScans) + " scans");
  }
  const std::string reason = std::string("libjpeg: ") + errors.message;
  return errors.truncated ? truncated(name, "JPEG", reason) : corrupt(name, "JPEG", reason);
}

}  // namespace animkit::image_detail
