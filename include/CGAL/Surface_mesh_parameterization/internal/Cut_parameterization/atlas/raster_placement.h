// Raster placement: charts placed on a bit image of the page, anywhere they
// fit, so that a small chart can go into a hole under another's overhang
// (where a skyline, which only sees the highest texel of each column, cannot).
//
// The page keeps, per texel row, 64-bit words of occupied texels: the placed
// rasters dilated by the padding (a square of p = ceil(padding) texels
// around each texel) and the p texels along the sides. A chart goes, in each
// of its 4 turns by 90°, at the lowest row, then the leftmost column, where
// the extent of each of its rows (a conservative superset of its texels)
// meets no occupied texel; the turn whose top ends lowest wins. A position is
// found by leapfrogging: the first free run of each row's length at or right
// of the current column, row after row, until all rows agree (a word scan
// skips 64 texels at a time). Then its exact texels are marked, dilated.
// Two placed charts' texels are thus more than p texels apart (Chebyshev).
#ifndef CGAL_SMP_CUT_INTERNAL_RASTER_PLACEMENT_H
#define CGAL_SMP_CUT_INTERNAL_RASTER_PLACEMENT_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_raster.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace packing {

/// Index of the lowest set bit of `w` (w != 0).
inline int lowest_bit(std::uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(w);
#else
  int k = 0;
  for(; !(w & 1); w >>= 1) ++k;
  return k;
#endif
}

/// Number of set bits of `w`.
inline int set_bit_count(std::uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_popcountll(w);
#else
  int k = 0;
  for(; w; w &= w - 1) ++k;
  return k;
#endif
}

/// Occupancy bit image of an `n` × `n` texel page (rows of 64-bit words).
/// Invariant: a set bit is a texel of the border (less than `pad` from a
/// side, or past the side in the last word) or within `pad` texels
/// (Chebyshev) of a texel of a placed raster.
class Raster_page
{
  int n_, pad_, words_;
  long free_;                         // clear texels
  int full_ = 0;                      // rows below are full
  std::vector<std::uint64_t> occ_;    // n_ rows of words_ words
  std::vector<int> run_;              // longest clear run of each row
  std::vector<int> lo_, hi_, order_;  // per row of the turned raster: extent; rows by decreasing extent
  std::vector<std::uint64_t> scratch_;

  const std::uint64_t* row(int y) const { return &occ_[std::size_t(y) * words_]; }

  /// First clear bit of row `r` at or after `q`; INT_MAX if none.
  int next_clear(const std::uint64_t* r, int q) const
  {
    if(q >= 64 * words_) return INT_MAX; // past the row's last word
    int k = q / 64;
    std::uint64_t w = ~r[k] & (~std::uint64_t(0) << (q % 64));
    while(!w)
    {
      if(++k == words_) return INT_MAX;
      w = ~r[k];
    }
    return 64 * k + lowest_bit(w);
  }

  /// First set bit of row `r` in [q, end) (end <= 64 · words); -1 if none.
  int next_set(const std::uint64_t* r, int q, int end) const
  {
    int k = q / 64;
    std::uint64_t w = r[k] & (~std::uint64_t(0) << (q % 64));
    while(!w)
    {
      if(64 * ++k >= end) return -1;
      w = r[k];
    }
    const int s = 64 * k + lowest_bit(w);
    return s < end ? s : -1;
  }

  /// First q >= p such that bits [q, q + length) of row `r` are clear; INT_MAX if none.
  int next_run(const std::uint64_t* r, int p, int length) const
  {
    for(int q = p;;)
    {
      q = next_clear(r, q);
      if(q == INT_MAX || q + length > n_) return INT_MAX;
      const int s = next_set(r, q, q + length);
      if(s < 0) return q;
      q = s + 1; // a run starting before s ends at s
    }
  }

  void update_run(int y)
  {
    int longest = 0;
    for(int q = 0; (q = next_clear(row(y), q)) < n_;)
    {
      const int s = next_set(row(y), q, 64 * words_);
      const int end = s < 0 ? n_ : (std::min)(s, n_);
      longest = (std::max)(longest, end - q);
      q = end;
    }
    run_[y] = longest;
  }

  /// Row extents of raster `r` turned by `turn` (see turned_profiles): returns the number of rows.
  int turned_rows(const Chart_raster& r, int turn)
  {
    const int h = (turn % 2) ? r.w : r.h;
    lo_.resize(h); hi_.resize(h);
    for(int k = 0; k < h; ++k)
      switch(turn)
      {
        case 0: lo_[k] = r.row_lo[k]; hi_[k] = r.row_hi[k]; break;
        case 1: lo_[k] = r.h - 1 - r.col_hi[k]; hi_[k] = r.h - 1 - r.col_lo[k]; break;
        case 2: lo_[k] = r.w - 1 - r.row_hi[r.h - 1 - k]; hi_[k] = r.w - 1 - r.row_lo[r.h - 1 - k]; break;
        default: lo_[k] = r.col_lo[r.w - 1 - k]; hi_[k] = r.col_hi[r.w - 1 - k]; break;
      }
    order_.resize(h);
    std::iota(order_.begin(), order_.end(), 0);
    // the longest rows first: they fail first
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) { return hi_[a] - lo_[a] > hi_[b] - lo_[b]; });
    return h;
  }

  /// Leftmost x in [pad, n - pad - w] where rows y .. y + h - 1 hold the turned extents; -1 if none.
  int fit_x(int y, int w, int h) const
  {
    const int last = n_ - pad_ - w;
    int x = pad_, agreed = 0;
    for(int k = 0;; k = (k + 1) % h)
    {
      const int j = order_[k];
      const int q = next_run(row(y + j), x + lo_[j], hi_[j] - lo_[j] + 1);
      if(q == INT_MAX || q - lo_[j] > last) return -1;
      if(q - lo_[j] != x) { x = q - lo_[j]; agreed = 0; } // every row is tried again at the new x
      if(++agreed == h) return x; // counted after the move: a one-row raster fits at once
    }
  }

  /// Marks the texels of `r` placed at `at`, dilated by the padding.
  void mark(const Chart_raster& r, const Raster_placement& at)
  {
    const bool turned = at.turn % 2 != 0;
    const int w = turned ? r.h : r.w, h = turned ? r.w : r.h;
    const int first = (at.x - pad_) / 64, span = (at.x + w - 1 + pad_) / 64 - first + 1;
    scratch_.assign(std::size_t(h) * span, 0);
    for(int j = 0; j < r.h; ++j)
      for(int k = 0; k < r.words; ++k)
        for(std::uint64_t b = r.bits[std::size_t(j) * r.words + k]; b; b &= b - 1)
        {
          const int i = 64 * k + lowest_bit(b);
          int c, t; // column and row in the turned raster
          switch(at.turn)
          {
            case 0: c = i; t = j; break;
            case 1: c = r.h - 1 - j; t = i; break;
            case 2: c = r.w - 1 - i; t = r.h - 1 - j; break;
            default: c = j; t = r.w - 1 - i; break;
          }
          const int X = at.x + c - 64 * first;
          scratch_[std::size_t(t) * span + X / 64] |= std::uint64_t(1) << (X % 64);
        }
    std::vector<std::uint64_t> grown(span);
    for(int t = 0; t < h; ++t)
    {
      std::uint64_t* m = &scratch_[std::size_t(t) * span];
      for(int step = 0; step < pad_; ++step) // one texel left and right per step
      {
        for(int k = 0; k < span; ++k)
          grown[k] = m[k] | (m[k] << 1) | (m[k] >> 1) | (k > 0 ? m[k - 1] >> 63 : 0) |
                     (k + 1 < span ? m[k + 1] << 63 : 0);
        std::copy(grown.begin(), grown.end(), m);
      }
      for(int y = at.y + t - pad_; y <= at.y + t + pad_; ++y)
        for(int k = 0; k < span; ++k)
        {
          std::uint64_t& o = occ_[std::size_t(y) * words_ + first + k];
          free_ -= set_bit_count(m[k] & ~o);
          o |= m[k];
        }
    }
    for(int y = at.y - pad_; y < at.y + h + pad_; ++y) update_run(y);
    while(full_ < n_ && run_[full_] == 0) ++full_;
  }

public:
  /// An empty page. \pre n > 2 pad + 2, pad >= 0
  Raster_page(int n, int pad)
    : n_(n), pad_(pad), words_((n + 63) / 64), free_(long(n - 2 * pad) * (n - 2 * pad)),
      occ_(std::size_t(n) * words_, 0), run_(n, 0)
  {
    for(int y = 0; y < n; ++y)
    {
      std::uint64_t* r = &occ_[std::size_t(y) * words_];
      if(y < pad || y >= n - pad) set_bits(r, 0, 64 * words_ - 1);
      else
      {
        if(pad > 0) set_bits(r, 0, pad - 1);
        set_bits(r, n - pad, 64 * words_ - 1);
      }
      update_run(y);
    }
    while(full_ < n_ && run_[full_] == 0) ++full_;
  }

  /// Clear texels (inside the padding, away from placed charts): no more area can be added.
  long free_texels() const { return free_; }

  /// Places raster `r` at the lowest, then leftmost, position of each turn
  /// where its row extents meet no occupied texel, the turn whose top ends
  /// lowest (ties: the first turn), and marks it. False (nothing changed) if
  /// it fits nowhere.
  /// \post the raster lies in [pad, n - pad)² and its texels are more than
  ///   `pad` texels from those of every raster placed before
  bool drop(const Chart_raster& r, Raster_placement& placed)
  {
    long best_top = LONG_MAX;
    for(int turn = 0; turn < 4; ++turn)
    {
      const int w = (turn % 2) ? r.h : r.w, h = (turn % 2) ? r.w : r.h;
      if(w > n_ - 2 * pad_ || h > n_ - 2 * pad_) continue;
      turned_rows(r, turn);
      for(int y = (std::max)(pad_, full_); y <= n_ - pad_ - h && long(y) + h < best_top; ++y)
      {
        bool possible = true; // each row's longest clear run must hold its extent
        for(int k = 0; k < h && possible; ++k)
          possible = run_[y + order_[k]] > hi_[order_[k]] - lo_[order_[k]];
        if(!possible) continue;
        const int x = fit_x(y, w, h);
        if(x < 0) continue;
        best_top = long(y) + h;
        placed = {x, y, turn};
        break;
      }
    }
    if(best_top == LONG_MAX) return false;
    mark(r, placed);
    return true;
  }
};

} // namespace packing
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
