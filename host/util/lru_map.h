#pragma once
// A map that holds at most `capacity` entries: inserting past that drops the least recently used
// (found or inserted) first.

#include <cstddef>
#include <iterator>
#include <list>
#include <map>
#include <utility>

namespace hexray::inline util {

template <typename Key, typename Value>
class LruMap {
public:
    explicit LruMap(std::size_t capacity) : capacity_(capacity) {}

    // The entry for `key`, now the most recently used; null when there is none.
    Value* find(const Key& key) {
        const auto found = index_.find(key);
        if (found == index_.end()) {
            return nullptr;
        }
        entries_.splice(entries_.begin(), entries_, found->second);
        return &found->second->second;
    }

    // Adds `value` for `key` (which must be absent) as the most recently used, then drops the
    // least recently used entries beyond the capacity; the new one always stays.
    Value& insert(Key key, Value value) {
        entries_.emplace_front(std::move(key), std::move(value));
        index_.emplace(entries_.front().first, entries_.begin());
        while (entries_.size() > capacity_ && entries_.size() > 1) {
            index_.erase(entries_.back().first);
            entries_.pop_back();
        }
        return entries_.front().second;
    }

    template <typename Predicate>
    void eraseIf(const Predicate& predicate) {
        for (auto entry = entries_.begin(); entry != entries_.end();) {
            if (predicate(entry->first, entry->second)) {
                index_.erase(entry->first);
                entry = entries_.erase(entry);
            } else {
                ++entry;
            }
        }
    }

    void clear() {
        index_.clear();
        entries_.clear();
    }

    // Every value, most recently used first.
    template <typename Visit>
    void forEach(const Visit& visit) {
        for (auto& entry : entries_) {
            visit(entry.second);
        }
    }
    template <typename Visit>
    void forEach(const Visit& visit) const {
        for (const auto& entry : entries_) {
            visit(entry.second);
        }
    }

    std::size_t size() const { return entries_.size(); }
    std::size_t capacity() const { return capacity_; }

private:
    using Entries = std::list<std::pair<Key, Value>>;
    std::size_t capacity_;
    Entries entries_;  // most recently used first
    std::map<Key, typename Entries::iterator> index_;
};

}  // namespace hexray::util
