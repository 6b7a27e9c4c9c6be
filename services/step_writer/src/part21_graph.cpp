#include <algorithm>
#include <stdexcept>
#include <string>

#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::step_writer::part21 {

const Record* Instance::record(std::string_view entity) const {
  for (const auto& r : records)
    if (r.entity == entity) return &r;
  return nullptr;
}

InstanceId Graph::add(std::string_view entity, std::vector<Value> attributes) {
  Instance instance;
  instance.id = next_id_;
  instance.records.push_back(Record{std::string(entity), std::move(attributes)});
  insert(std::move(instance));
  return instances_.back().id;
}

InstanceId Graph::add_complex(std::vector<Record> records) {
  if (records.empty()) throw std::invalid_argument("a complex instance needs at least one record");
  std::sort(records.begin(), records.end(),
            [](const Record& a, const Record& b) { return a.entity < b.entity; });
  Instance instance;
  instance.id = next_id_;
  instance.records = std::move(records);
  instance.complex = true;
  insert(std::move(instance));
  return instances_.back().id;
}

InstanceId Graph::reserve() {
  Instance instance;
  instance.id = next_id_;
  insert(std::move(instance));
  return instances_.back().id;
}

void Graph::set(InstanceId id, std::string_view entity, std::vector<Value> attributes) {
  Instance* instance = find(id);
  if (!instance) throw std::out_of_range("Part 21 graph has no instance #" + std::to_string(id));
  instance->records.clear();
  instance->records.push_back(Record{std::string(entity), std::move(attributes)});
  instance->complex = false;
}

void Graph::insert(Instance instance) {
  if (instance.id == 0) throw std::invalid_argument("Part 21 instance id 0 is not allowed");
  if (index_.count(instance.id))
    throw std::invalid_argument("duplicate Part 21 instance #" + std::to_string(instance.id));
  next_id_ = std::max(next_id_, instance.id + 1);
  index_.emplace(instance.id, instances_.size());
  instances_.push_back(std::move(instance));
}

const Instance* Graph::find(InstanceId id) const {
  auto it = index_.find(id);
  return it == index_.end() ? nullptr : &instances_[it->second];
}

Instance* Graph::find(InstanceId id) {
  auto it = index_.find(id);
  return it == index_.end() ? nullptr : &instances_[it->second];
}

const Instance& Graph::at(InstanceId id) const {
  const Instance* instance = find(id);
  if (!instance) throw std::out_of_range("Part 21 graph has no instance #" + std::to_string(id));
  return *instance;
}

std::vector<InstanceId> Graph::ids_of(std::string_view entity) const {
  std::vector<InstanceId> ids;
  for (const auto& instance : instances_)
    if (instance.record(entity)) ids.push_back(instance.id);
  return ids;
}

}  // namespace ncbridge::step_writer::part21
