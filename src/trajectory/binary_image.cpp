#include "animkit/trajectory/binary_image.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace animkit {

int BinaryImage::count() const {
  return static_cast<int>(std::count(pixels.begin(), pixels.end(), std::uint8_t{1}));
}

std::optional<int> otsu_threshold(const GrayImage& image) {
  std::array<double, 256> histogram{};
  for (std::uint8_t v : image.pixels) histogram[v] += 1.0;
  const double total = static_cast<double>(image.pixels.size());
  double sum_all = 0.0;
  for (int t = 0; t < 256; ++t) sum_all += t * histogram[t];
  double weight_low = 0.0, sum_low = 0.0, best_variance = -1.0;
  std::optional<int> best;
  for (int t = 0; t < 255; ++t) {
    weight_low += histogram[t];
    sum_low += t * histogram[t];
    const double weight_high = total - weight_low;
    if (weight_low == 0.0 || weight_high == 0.0) continue;
    const double mean_low = sum_low / weight_low;
    const double mean_high = (sum_all - sum_low) / weight_high;
    // Between-class variance w0 w1 (m0 - m1)^2 (up to the constant 1 / total^2).
    const double variance =
        weight_low * weight_high * (mean_low - mean_high) * (mean_low - mean_high);
    if (variance > best_variance) {
      best_variance = variance;
      best = t;
    }
  }
  return best;
}

BinaryImage binarize(const GrayImage& image, int threshold, InkPolarity polarity) {
  BinaryImage out(image.width, image.height);
  if (polarity == InkPolarity::automatic) {
    // Paper is what the border is mostly made of (a drawing rarely touches every edge). A
    // tie, or an image that is all border (one or two pixels wide), says nothing: then ink is
    // dark, as a pen on paper.
    std::size_t dark_border = 0, border = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        if (y != 0 && y != image.height - 1 && x != 0 && x != image.width - 1) continue;
        dark_border += image.at(x, y) <= threshold ? 1 : 0;
        ++border;
      }
    }
    const bool dark_paper = 2 * dark_border > border && border < image.pixels.size();
    polarity = dark_paper ? InkPolarity::light : InkPolarity::dark;
  }
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const bool low = image.pixels[i] <= threshold;
    out.pixels[i] = (polarity == InkPolarity::dark) == low ? 1 : 0;
  }
  return out;
}

Components connected_components(const BinaryImage& image) {
  Components c;
  c.label.assign(image.pixels.size(), -1);
  std::vector<int> stack;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const int start = y * image.width + x;
      if (!image.pixels[start] || c.label[start] >= 0) continue;
      const int id = static_cast<int>(c.sizes.size());
      c.sizes.push_back(0);
      c.label[start] = id;
      stack.push_back(start);
      while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        ++c.sizes[id];
        const int px = p % image.width, py = p / image.width;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = px + dx, qy = py + dy;
            if (!image.get(qx, qy)) continue;
            const int q = qy * image.width + qx;
            if (c.label[q] < 0) {
              c.label[q] = id;
              stack.push_back(q);
            }
          }
        }
      }
    }
  }
  return c;
}

int remove_specks(BinaryImage& image, int min_pixels) {
  const Components c = connected_components(image);
  int removed = 0;
  for (int size : c.sizes) removed += size < min_pixels ? 1 : 0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (c.label[i] >= 0 && c.sizes[c.label[i]] < min_pixels) image.pixels[i] = 0;
  }
  return removed;
}

std::string_view to_string(ThinningMethod method) {
  return method == ThinningMethod::zhang_suen ? "zhang-suen" : "guo-hall";
}

std::optional<ThinningMethod> parse_thinning(std::string_view name) {
  if (name == "zhang-suen") return ThinningMethod::zhang_suen;
  if (name == "guo-hall") return ThinningMethod::guo_hall;
  return std::nullopt;
}

namespace {

// The 8 neighbours P2..P9 of a pixel, clockwise from north, as both papers number them.
std::array<int, 8> neighbours(const BinaryImage& im, int x, int y) {
  return {im.get(x, y - 1), im.get(x + 1, y - 1), im.get(x + 1, y), im.get(x + 1, y + 1),
          im.get(x, y + 1), im.get(x - 1, y + 1), im.get(x - 1, y), im.get(x - 1, y - 1)};
}

// Zhang & Suen, "A fast parallel algorithm for thinning digital patterns" (CACM 1984): a
// pixel is deleted in sub-iteration `pass` when B <= 6, A = 1 (one 0->1 transition around it)
// and the pass's two directional products vanish. The lower bound is Lu & Wang's (CACM 1986)
// 3 <= B instead of 2 <= B: with 2, a two-pixel-wide 45-degree line is eaten from its ends.
bool zhang_suen_deletes(const std::array<int, 8>& p, int pass) {
  const int b = std::accumulate(p.begin(), p.end(), 0);
  if (b < 3 || b > 6) return false;
  int a = 0;
  for (int i = 0; i < 8; ++i) a += (p[i] == 0 && p[(i + 1) % 8] == 1) ? 1 : 0;
  if (a != 1) return false;
  const int p2 = p[0], p4 = p[2], p6 = p[4], p8 = p[6];
  return pass == 0 ? (p2 * p4 * p6 == 0 && p4 * p6 * p8 == 0)
                   : (p2 * p4 * p8 == 0 && p2 * p6 * p8 == 0);
}

// Guo & Hall, "Parallel thinning with two-subiteration algorithms" (CACM 1989), algorithm A1:
// C(P) = 1, 2 <= N(P) <= 3 and the pass's directional condition.
bool guo_hall_deletes(const std::array<int, 8>& p, int pass) {
  const int p2 = p[0], p3 = p[1], p4 = p[2], p5 = p[3], p6 = p[4], p7 = p[5], p8 = p[6], p9 = p[7];
  const auto no = [](int v) { return 1 - v; };
  const int c =
      (no(p2) & (p3 | p4)) + (no(p4) & (p5 | p6)) + (no(p6) & (p7 | p8)) + (no(p8) & (p9 | p2));
  const int n1 = (p9 | p2) + (p3 | p4) + (p5 | p6) + (p7 | p8);
  const int n2 = (p2 | p3) + (p4 | p5) + (p6 | p7) + (p8 | p9);
  const int n = std::min(n1, n2);
  const int m = pass == 0 ? ((p6 | p7 | no(p9)) & p8) : ((p2 | p3 | no(p5)) & p4);
  return c == 1 && n >= 2 && n <= 3 && m == 0;
}

// Whether (x, y) can go without changing the topology and without shortening a line: it has
// at least two ink neighbours and Yokoi's 8-connectivity number
//   N8 = sum over the 4-neighbours k of (q_k - q_k q_{k+1} q_{k+2}),  q = 1 - p,
// is 1 (Yokoi, Toriwaki & Fukumura 1975): its neighbours' ink is one piece, with no hole.
bool simple_and_not_end(const BinaryImage& im, int x, int y) {
  const std::array<int, 8> p = neighbours(im, x, y);
  if (std::accumulate(p.begin(), p.end(), 0) < 2) return false;
  int n8 = 0;
  for (int k = 0; k < 8; k += 2) {
    const int q0 = 1 - p[k], q1 = 1 - p[(k + 1) % 8], q2 = 1 - p[(k + 2) % 8];
    n8 += q0 - q0 * q1 * q2;
  }
  return n8 == 1;
}

}  // namespace

void thin(BinaryImage& image, ThinningMethod method) {
  std::vector<int> doomed;
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      doomed.clear();
      for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
          if (!image.get(x, y)) continue;
          const auto p = neighbours(image, x, y);
          const bool deletes = method == ThinningMethod::zhang_suen ? zhang_suen_deletes(p, pass)
                                                                    : guo_hall_deletes(p, pass);
          if (deletes) doomed.push_back(y * image.width + x);
        }
      }
      for (int i : doomed) image.pixels[i] = 0;
      changed = changed || !doomed.empty();
    }
  }
  // Both methods can leave 2x2 blocks of ink on diagonal staircases; a pixel of such a block
  // whose removal keeps its neighbourhood in one piece is redundant.
  for (bool cleaned = true; cleaned;) {
    cleaned = false;
    for (int y = 0; y + 1 < image.height; ++y) {
      for (int x = 0; x + 1 < image.width; ++x) {
        if (!(image.get(x, y) && image.get(x + 1, y) && image.get(x, y + 1) &&
              image.get(x + 1, y + 1))) {
          continue;
        }
        for (const auto& [px, py] :
             {std::pair{x, y}, std::pair{x + 1, y}, std::pair{x, y + 1}, std::pair{x + 1, y + 1}}) {
          if (simple_and_not_end(image, px, py)) {
            image.set(px, py, 0);
            cleaned = true;
            break;
          }
        }
      }
    }
  }
}

}  // namespace animkit
