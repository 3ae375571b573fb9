// SharedList<T>: a vector whose copies share their items until one is written
// (docs/architecture.md, "Documents shared by their copies"). The document's
// sections (objects, materials, lights, strokes, tracks) are SharedLists, so a
// copy of a 20,000-object document costs a few kilobytes of pointers, and an edit
// of one object copies that object and the 64 pointers of its chunk.
//
// Reading is a vector's. A write through a non-const operator[], at(), back() or
// iterator first makes the item's chunk and the item this list's own: the list
// it was copied from, and every other copy, keep what they had. As with any
// copy-on-write container, a reference taken for writing must not outlive a copy
// of the list made after it (it would write into an item the copy shares).
#pragma once

#include <algorithm>
#include <compare>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace inkray {

template <class T>
class SharedList {
  // Items per chunk: a list of n items copies n / 64 chunk pointers, an edit 64 item pointers.
  static constexpr size_t kChunk = 64;
  struct Chunk {
    std::vector<std::shared_ptr<T>> items;  // at most kChunk; only the last chunk holds fewer
  };

  template <bool kConst>
  class Iterator {
    using List = std::conditional_t<kConst, const SharedList, SharedList>;

   public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using reference = std::conditional_t<kConst, const T&, T&>;
    using pointer = std::conditional_t<kConst, const T*, T*>;

    Iterator() = default;
    Iterator(List* list, size_t index) : list_(list), index_(index) {}
    operator Iterator<true>() const  // NOLINT: converts as a vector's iterator does
        requires(!kConst) {
      return {list_, index_};
    }

    reference operator*() const { return (*list_)[index_]; }
    pointer operator->() const { return &(*list_)[index_]; }
    reference operator[](difference_type n) const { return (*list_)[size_t(difference_type(index_) + n)]; }
    Iterator& operator++() { return ++index_, *this; }
    Iterator& operator--() { return --index_, *this; }
    Iterator operator++(int) { return {list_, index_++}; }
    Iterator operator--(int) { return {list_, index_--}; }
    Iterator& operator+=(difference_type n) { return index_ = size_t(difference_type(index_) + n), *this; }
    Iterator& operator-=(difference_type n) { return *this += -n; }
    friend Iterator operator+(Iterator it, difference_type n) { return it += n; }
    friend Iterator operator+(difference_type n, Iterator it) { return it += n; }
    friend Iterator operator-(Iterator it, difference_type n) { return it -= n; }
    friend difference_type operator-(const Iterator& a, const Iterator& b) {
      return difference_type(a.index_) - difference_type(b.index_);
    }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.index_ == b.index_; }
    friend auto operator<=>(const Iterator& a, const Iterator& b) { return a.index_ <=> b.index_; }
    size_t index() const { return index_; }

   private:
    List* list_ = nullptr;
    size_t index_ = 0;
  };

 public:
  using value_type = T;
  using size_type = size_t;
  using difference_type = std::ptrdiff_t;
  using reference = T&;
  using const_reference = const T&;
  using iterator = Iterator<false>;
  using const_iterator = Iterator<true>;

  SharedList() = default;
  SharedList(std::initializer_list<T> items) : SharedList(std::vector<T>(items)) {}
  SharedList(std::vector<T> items) {  // NOLINT: a vector is a list, as in a document's initialiser
    std::vector<std::shared_ptr<T>> pointers;
    pointers.reserve(items.size());
    for (T& item : items) pointers.push_back(std::make_shared<T>(std::move(item)));
    rechunk(std::move(pointers));
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  const T& operator[](size_t i) const { return *chunks_[i / kChunk]->items[i % kChunk]; }
  T& operator[](size_t i) { return own(i); }
  const T& at(size_t i) const { return i < size_ ? (*this)[i] : throw std::out_of_range("SharedList::at"); }
  T& at(size_t i) { return i < size_ ? (*this)[i] : throw std::out_of_range("SharedList::at"); }
  const T& front() const { return (*this)[0]; }
  T& front() { return (*this)[0]; }
  const T& back() const { return (*this)[size_ - 1]; }
  T& back() { return (*this)[size_ - 1]; }

  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size_}; }
  const_iterator cbegin() const { return begin(); }
  const_iterator cend() const { return end(); }
  iterator begin() { return {this, 0}; }
  iterator end() { return {this, size_}; }

  // Whether item i is the same object in both lists: unchanged since one was copied from
  // the other, and equal without comparing it.
  bool shares(const SharedList& other, size_t i) const {
    return i < size_ && i < other.size_ && pointer(i) == other.pointer(i);
  }

  void push_back(T item) { emplace_back(std::move(item)); }
  template <class... Args>
  T& emplace_back(Args&&... args) {
    if (size_ % kChunk == 0) chunks_.push_back(std::make_shared<Chunk>());
    auto& chunk = own_chunk(chunks_.size() - 1);
    chunk.items.push_back(std::make_shared<T>(std::forward<Args>(args)...));
    ++size_;
    return *chunk.items.back();
  }
  // The last chunk only: the others stay shared.
  void pop_back() {
    own_chunk(chunks_.size() - 1).items.pop_back();
    if (chunks_.back()->items.empty()) chunks_.pop_back();
    --size_;
  }

  iterator insert(const_iterator at, T item) {
    std::vector<std::shared_ptr<T>> pointers = all_pointers();
    const size_t i = at.index();
    pointers.insert(pointers.begin() + difference_type(i), std::make_shared<T>(std::move(item)));
    rechunk(std::move(pointers));
    return {this, i};
  }
  iterator erase(const_iterator at) { return erase(at, at + 1); }
  iterator erase(const_iterator first, const_iterator last) {
    std::vector<std::shared_ptr<T>> pointers = all_pointers();
    pointers.erase(pointers.begin() + difference_type(first.index()),
                   pointers.begin() + difference_type(last.index()));
    rechunk(std::move(pointers));
    return {this, first.index()};
  }
  // Removes the items `remove` is true of; the rest keep their order and stay shared.
  template <class Predicate>
  size_t erase_if(Predicate remove) {
    std::vector<std::shared_ptr<T>> pointers = all_pointers();
    const size_t before = pointers.size();
    std::erase_if(pointers, [&](const std::shared_ptr<T>& p) { return remove(std::as_const(*p)); });
    const size_t removed = before - pointers.size();
    if (removed) rechunk(std::move(pointers));
    return removed;
  }
  // Applies `change` to the items `select` is true of, which alone are taken for writing:
  // a rename that touches three objects of 20,000 copies three. Returns how many.
  template <class Select, class Change>
  size_t update_if(Select select, Change change) {
    size_t changed = 0;
    for (size_t i = 0; i < size_; ++i) {
      if (!select(std::as_const(*this)[i])) continue;
      change((*this)[i]);
      ++changed;
    }
    return changed;
  }
  void clear() {
    chunks_.clear();
    size_ = 0;
  }
  void reserve(size_t n) { chunks_.reserve((n + kChunk - 1) / kChunk); }
  void resize(size_t n) {
    if (n < size_) erase(begin() + difference_type(n), end());
    while (size_ < n) emplace_back();
  }

  std::vector<T> to_vector() const { return std::vector<T>(begin(), end()); }

  friend bool operator==(const SharedList& a, const SharedList& b) {
    if (a.size_ != b.size_) return false;
    for (size_t c = 0; c < a.chunks_.size(); ++c) {
      if (a.chunks_[c] == b.chunks_[c]) continue;
      const auto& x = a.chunks_[c]->items;
      const auto& y = b.chunks_[c]->items;
      for (size_t i = 0; i < x.size(); ++i)
        if (x[i] != y[i] && !(*x[i] == *y[i])) return false;
    }
    return true;
  }

 private:
  const T* pointer(size_t i) const { return chunks_[i / kChunk]->items[i % kChunk].get(); }

  // This list's own copy of chunk c: copied (its item pointers, not its items) while shared.
  Chunk& own_chunk(size_t c) {
    auto& chunk = chunks_[c];
    if (chunk.use_count() > 1) chunk = std::make_shared<Chunk>(*chunk);
    return *chunk;
  }
  // This list's own copy of item i, for writing.
  T& own(size_t i) {
    auto& item = own_chunk(i / kChunk).items[i % kChunk];
    if (item.use_count() > 1) item = std::make_shared<T>(std::as_const(*item));
    return *item;
  }

  std::vector<std::shared_ptr<T>> all_pointers() const {
    std::vector<std::shared_ptr<T>> pointers;
    pointers.reserve(size_);
    for (const auto& chunk : chunks_)
      pointers.insert(pointers.end(), chunk->items.begin(), chunk->items.end());
    return pointers;
  }
  // Lays the items out in chunks again (after an insertion or removal): the items stay
  // shared; only the chunks are new.
  void rechunk(std::vector<std::shared_ptr<T>> pointers) {
    chunks_.clear();
    size_ = pointers.size();
    for (size_t first = 0; first < pointers.size(); first += kChunk) {
      auto chunk = std::make_shared<Chunk>();
      const size_t last = std::min(first + kChunk, pointers.size());
      chunk->items.assign(std::make_move_iterator(pointers.begin() + difference_type(first)),
                          std::make_move_iterator(pointers.begin() + difference_type(last)));
      chunks_.push_back(std::move(chunk));
    }
  }

  std::vector<std::shared_ptr<Chunk>> chunks_;
  size_t size_ = 0;
};

}  // namespace inkray
