#pragma once
// Many short lists in one pool: each list is a chain of links through one array, and links freed
// by clearing a list are reused by the next pushes. The solver keeps a list per alternating tree
// (its labelled blossoms, the edges parked with it); with a std::vector per tree, growing and
// freeing 145k vectors on armadillo-sub2's dual would cost 18 % of the solver's instructions in
// malloc, free and the copies of regrowth.

#include <cstdint>
#include <vector>

namespace petersen::weighted_detail {

template <class Value>
class ChainPool {
 public:
  static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;

  /// Puts value at the front of the list starting at head.
  void push(std::uint32_t& head, const Value& value) {
    std::uint32_t link;
    if (free_ != kEnd) {
      link = free_;
      free_ = links_[link].next;
      links_[link] = {value, head};
    } else {
      link = static_cast<std::uint32_t>(links_.size());
      links_.push_back({value, head});
    }
    head = link;
  }

  /// Calls visit(value) for each value of the list at head, newest first, and empties it.
  template <class Visit>
  void drain(std::uint32_t& head, Visit&& visit) {
    for (std::uint32_t link = head; link != kEnd;) {
      const std::uint32_t next = links_[link].next;
      visit(links_[link].value);
      links_[link].next = free_;
      free_ = link;
      link = next;
    }
    head = kEnd;
  }

 private:
  struct Link {
    Value value;
    std::uint32_t next;
  };
  std::vector<Link> links_;
  std::uint32_t free_ = kEnd;
};

}  // namespace petersen::weighted_detail
