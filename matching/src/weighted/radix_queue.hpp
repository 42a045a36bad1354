#pragma once
// A monotone priority queue on integer keys (a radix heap): the key taken out never decreases,
// and every key put in is at least the last one taken out. An item lives in the bucket named by
// the highest 6-bit digit in which its key differs from the last key taken and by its value in
// that digit (the current key's own items in bucket 0); taking out empties bucket 0, or else
// takes the first non-empty bucket (a bitmap finds it): on the lowest digit all its keys are
// equal and it becomes bucket 0 whole, higher up its items move around its smallest key (kept
// per bucket) to buckets of lower digits. An item moves at most once per digit: 2 moves per item
// taken with 4-bit digits against 6 with one bucket per bit (armadillo-sub2's dual), where the
// moves, the scans for the first non-empty bucket and for a bucket's smallest key are 17 % of
// the solver's instructions (armadillo's dual). 6-bit digits against 4 (fertility-sub3's dual):
// 5.7 % fewer of the solver's instructions, 1.7 % more D1 and 1 % more last-level read misses;
// 8-bit: 9.1 % fewer instructions, 4.6 % and 3.4 % more misses. The buckets are read
// sequentially, where a binary heap misses the cache on every level of a 3M-entry heap (27 % of
// the time on fertility-sub3's dual).

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace petersen::weighted_detail {

template <class Item>
class RadixQueue {
 public:
  RadixQueue() = default;
  RadixQueue(const RadixQueue&) = delete;
  RadixQueue& operator=(const RadixQueue&) = delete;

  bool empty() const { return size_ == 0; }

  /// Puts item with key >= the last key taken out.
  [[gnu::always_inline]] void push(std::uint64_t key, const Item& item) {
    const int b = bucket_of(key);
    append(b, {key, item});
    if (key < least_[b]) least_[b] = key;
    nonempty_[b / 64] |= std::uint64_t{1} << (b % 64);
    ++size_;
  }

  /// Takes out an item of the smallest key (queue not empty); returns its key.
  std::uint64_t pop(Item& item) {
    if (top_[0] == nullptr) refill();
    item = top_[0]->entries[--fill_[0]].item;
    if (fill_[0] == 0) {
      drop_top(0);
      if (top_[0] == nullptr) nonempty_[0] &= ~std::uint64_t{1};
    }
    --size_;
    return last_;
  }

 private:
  static constexpr int kDigitBits = 6;
  static constexpr int kDigits = 1 << kDigitBits;
  static constexpr int kLevels = (64 + kDigitBits - 1) / kDigitBits;
  static constexpr int kBuckets = 1 + kLevels * kDigits;  // 0: the current key
  static constexpr int kWords = (kBuckets + 63) / 64;
  static constexpr std::uint64_t kNoKey = std::numeric_limits<std::uint64_t>::max();
  static constexpr std::uint32_t kBlockEntries = 64;

  struct Entry {
    std::uint64_t key;
    Item item;
  };
  // A bucket is a stack of blocks, the top one filling; every block below it is full, and an
  // empty bucket counts as a full block (fill_ = kBlockEntries, no top), so that one test tells
  // a push when to take a block. Freed blocks go to a shared free list: a bucket grows without
  // copying what it holds. With a std::vector per bucket, the growth copies (a bucket's items
  // moving to buckets of lower digits refill them from empty again and again) would be 5 % of the
  // solver's instructions and 60 % of its last-level write misses on armadillo's dual.
  struct Block {
    Block* below = nullptr;
    std::array<Entry, kBlockEntries> entries;
  };

  int bucket_of(std::uint64_t key) const {
    if (key == last_) return 0;
    const int level = (63 - std::countl_zero(key ^ last_)) / kDigitBits;
    return 1 + level * kDigits + static_cast<int>((key >> (level * kDigitBits)) & (kDigits - 1));
  }

  [[gnu::always_inline]] void append(int b, const Entry& entry) {
    if (fill_[b] == kBlockEntries) [[unlikely]] {
      Block* block = free_;
      if (block != nullptr) {
        free_ = block->below;
      } else {
        owned_.push_back(std::make_unique<Block>());
        block = owned_.back().get();
      }
      block->below = top_[b];
      top_[b] = block;
      fill_[b] = 0;
    }
    top_[b]->entries[fill_[b]++] = entry;
  }

  // Frees bucket b's top block; the one below, if any, is full.
  void drop_top(int b) {
    Block* block = top_[b];
    top_[b] = block->below;
    fill_[b] = kBlockEntries;
    block->below = free_;
    free_ = block;
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
    least_[b] = kNoKey;
    nonempty_[b / 64] &= ~(std::uint64_t{1} << (b % 64));
    if (b <= kDigits) {  // the lowest digit: every key here is last_
      top_[0] = top_[b];
      fill_[0] = fill_[b];
      top_[b] = nullptr;
      fill_[b] = kBlockEntries;
    } else {
      // Oldest block first, in the order the items came in: the chain is reversed in place.
      Block* oldest = nullptr;
      for (Block* block = top_[b]; block != nullptr;) {
        Block* const below = block->below;
        block->below = oldest;
        oldest = block;
        block = below;
      }
      const std::uint32_t top_fill = fill_[b];
      top_[b] = nullptr;
      fill_[b] = kBlockEntries;
      for (Block* block = oldest; block != nullptr;) {
        Block* const newer = block->below;
        const std::uint32_t count = newer == nullptr ? top_fill : kBlockEntries;
        for (std::uint32_t at = 0; at < count; ++at) {
          const Entry& entry = block->entries[at];
          const int to = bucket_of(entry.key);
          append(to, entry);
          if (entry.key < least_[to]) least_[to] = entry.key;
          nonempty_[to / 64] |= std::uint64_t{1} << (to % 64);
        }
        block->below = free_;
        free_ = block;
        block = newer;
      }
    }
    nonempty_[0] |= 1;
  }

  std::array<Block*, kBuckets> top_{};
  std::array<std::uint32_t, kBuckets> fill_ = filled<std::uint32_t>(kBlockEntries);
  std::array<std::uint64_t, kBuckets> least_ = filled<std::uint64_t>(kNoKey);
  std::array<std::uint64_t, kWords> nonempty_{};
  std::size_t size_ = 0;
  std::uint64_t last_ = 0;
  Block* free_ = nullptr;
  std::vector<std::unique_ptr<Block>> owned_;

  template <class T>
  static constexpr std::array<T, kBuckets> filled(T value) {
    std::array<T, kBuckets> a{};
    a.fill(value);
    return a;
  }
};

}  // namespace petersen::weighted_detail
