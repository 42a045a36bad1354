#pragma once
// A monotone priority queue on integer keys (a radix heap): the key taken out never decreases,
// and every key put in is at least the last one taken out. An item lives in the bucket named by
// the highest 4-bit digit in which its key differs from the last key taken and by its value in
// that digit (the current key's own items in bucket 0); taking out empties bucket 0, or else
// takes the first non-empty bucket (a bitmap finds it): on the lowest digit all its keys are
// equal and it becomes bucket 0 whole, higher up its items move around its smallest key (kept
// per bucket) to buckets of lower digits. An item moves at most once per digit: 2 moves per item
// taken instead of 6 with one bucket per bit (armadillo-sub2's dual), where the moves, the scans
// for the first non-empty bucket and for a bucket's smallest key were 17 % of the solver's
// instructions (callgrind, armadillo's dual). The buckets are read sequentially: the binary heap
// before them missed the cache on every level of a 3M-entry heap (27 % of the time on
// fertility-sub3's dual).

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

namespace petersen::weighted_detail {

template <class Item>
class RadixQueue {
 public:
  bool empty() const { return size_ == 0; }

  /// Puts item with key >= the last key taken out.
  [[gnu::always_inline]] void push(std::uint64_t key, const Item& item) {
    const int b = bucket_of(key);
    buckets_[b].push_back({key, item});
    if (key < least_[b]) least_[b] = key;
    nonempty_[b / 64] |= std::uint64_t{1} << (b % 64);
    ++size_;
  }

  /// Takes out an item of the smallest key (queue not empty); returns its key.
  std::uint64_t pop(Item& item) {
    if (buckets_[0].empty()) refill();
    item = buckets_[0].back().item;
    buckets_[0].pop_back();
    if (buckets_[0].empty()) nonempty_[0] &= ~std::uint64_t{1};
    --size_;
    return last_;
  }

 private:
  static constexpr int kDigitBits = 4;
  static constexpr int kDigits = 1 << kDigitBits;
  static constexpr int kBuckets = 1 + 64 / kDigitBits * kDigits;  // 0: the current key
  static constexpr int kWords = (kBuckets + 63) / 64;
  static constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();

  struct Entry {
    std::uint64_t key;
    Item item;
  };

  int bucket_of(std::uint64_t key) const {
    if (key == last_) return 0;
    const int level = (63 - std::countl_zero(key ^ last_)) / kDigitBits;
    return 1 + level * kDigits + static_cast<int>((key >> (level * kDigitBits)) & (kDigits - 1));
  }

  // Bucket 0 is empty: makes the first non-empty bucket's smallest key the current one and
  // brings its items with that key to bucket 0.
  void refill() {
    int b = 0;
    for (int w = 0; w < kWords; ++w) {
      if (nonempty_[w] != 0) {
        b = w * 64 + std::countr_zero(nonempty_[w]);
        break;
      }
    }
    last_ = least_[b];
    std::vector<Entry>& from = buckets_[b];
    least_[b] = kNoKey;
    nonempty_[b / 64] &= ~(std::uint64_t{1} << (b % 64));
    if (b <= kDigits) {  // the lowest digit: every key here is last_
      std::swap(buckets_[0], from);
    } else {
      for (const Entry& entry : from) {
        const int to = bucket_of(entry.key);
        buckets_[to].push_back(entry);
        if (entry.key < least_[to]) least_[to] = entry.key;
        nonempty_[to / 64] |= std::uint64_t{1} << (to % 64);
      }
      from.clear();
    }
    nonempty_[0] |= 1;
  }

  std::array<std::vector<Entry>, kBuckets> buckets_;
  std::array<std::uint64_t, kBuckets> least_ = filled(kNoKey);
  std::array<std::uint64_t, kWords> nonempty_{};
  std::size_t size_ = 0;
  std::uint64_t last_ = 0;

  static constexpr std::array<std::uint64_t, kBuckets> filled(std::uint64_t value) {
    std::array<std::uint64_t, kBuckets> a{};
    a.fill(value);
    return a;
  }
};

}  // namespace petersen::weighted_detail
