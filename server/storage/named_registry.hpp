#pragma once
// What clients name (maps, model assets), by name: at most a given number, handed out as shared_ptr<const T>
// so a removal never pulls an entry out from under a request working with it. A name can be held while
// its entry is made (an upload): a held name is taken and counts against the maximum. Thread-safe.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace lp::server {

// How refusals name what a registry holds.
struct RegistryWording {
  std::string one;     // "an asset", as in "an asset named 'x' exists"
  std::string kind;    // "asset", as in "no asset named 'x'"
  std::string lookup;  // "named", as in "no asset named 'x'"
  std::string limit;   // "assets (--max-assets 10)", as in "the server holds the maximum number of ..."
};

// Throw ApiError 409 conflict, 507 insufficient_storage and 404 not_found.
[[noreturn]] void refuse_taken(const RegistryWording& wording, const std::string& name);
[[noreturn]] void refuse_full(const RegistryWording& wording);
[[noreturn]] void refuse_absent(const RegistryWording& wording, const std::string& name);

template <typename T>
class NamedRegistry {
 public:
  // A name held for an entry in the making; released on destruction unless the entry was added.
  class Hold {
   public:
    Hold(NamedRegistry& registry, std::string name) : registry_(&registry), name_(std::move(name)) {}
    ~Hold() {
      if (!added_) registry_->release(name_);
    }
    Hold(const Hold&) = delete;
    Hold& operator=(const Hold&) = delete;

    const std::string& name() const { return name_; }
    std::shared_ptr<const T> add(T entry) {
      auto added = registry_->put(name_, std::move(entry));
      added_ = true;
      return added;
    }

   private:
    NamedRegistry* registry_;
    std::string name_;
    bool added_ = false;
  };

  NamedRegistry(int64_t max_entries, RegistryWording wording)
      : max_entries_(max_entries), wording_(std::move(wording)) {}

  // Throws ApiError 409 if the name is taken or held, 507 when the entries and held names reach the
  // maximum.
  std::unique_ptr<Hold> hold(const std::string& name) {
    std::lock_guard lock(mutex_);
    if (entries_.count(name) || held_.count(name)) refuse_taken(wording_, name);
    if (int64_t(entries_.size() + held_.size()) >= max_entries_) refuse_full(wording_);
    held_.insert(name);
    return std::make_unique<Hold>(*this, name);
  }
  // hold(name)->add(entry).
  std::shared_ptr<const T> add(const std::string& name, T entry) { return hold(name)->add(std::move(entry)); }

  std::shared_ptr<const T> find(const std::string& name) const {  // nullptr if absent
    std::lock_guard lock(mutex_);
    const auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : it->second;
  }
  std::shared_ptr<const T> get(const std::string& name) const {  // throws ApiError 404
    auto entry = find(name);
    if (!entry) refuse_absent(wording_, name);
    return entry;
  }
  bool remove(const std::string& name) {
    std::lock_guard lock(mutex_);
    return entries_.erase(name) > 0;
  }
  std::vector<std::shared_ptr<const T>> list() const {  // by name
    std::lock_guard lock(mutex_);
    std::vector<std::shared_ptr<const T>> out;
    for (const auto& [name, entry] : entries_) out.push_back(entry);
    return out;
  }

 private:
  std::shared_ptr<const T> put(const std::string& name, T entry) {
    auto shared = std::make_shared<const T>(std::move(entry));
    std::lock_guard lock(mutex_);
    held_.erase(name);
    entries_[name] = shared;
    return shared;
  }
  void release(const std::string& name) {
    std::lock_guard lock(mutex_);
    held_.erase(name);
  }

  const int64_t max_entries_;
  const RegistryWording wording_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const T>> entries_;
  std::set<std::string> held_;
};

}  // namespace lp::server
