#pragma once
// The in-memory instance graph of a Part 21 exchange structure: header + entity instances.
//
// Instances keep the order they were added (the reader adds them in file order); the writer
// writes them in that order with their ids, so the same graph always gives the same bytes.
// Builders call add(...) and get consecutive ids 1, 2, 3 ...; references may point forward
// (reserve() an id first, fill it later with set()).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "ncbridge/step_writer/part21_value.hpp"

namespace ncbridge::step_writer::part21 {

// One entity record: ENTITY_NAME(attr, attr, ...). A complex instance has several.
struct Record {
  std::string entity;  // upper case
  std::vector<Value> attributes;
  friend bool operator==(const Record&, const Record&) = default;
};

struct Instance {
  InstanceId id = 0;
  std::vector<Record> records;  // simple instance: exactly one; complex: one per partial entity
  bool complex = false;         // written as #n=(A(..)B(..)); records sorted by entity name
  std::uint32_t line = 0;       // where the reader found `#n`; 0 for built instances
  std::uint32_t column = 0;

  const std::string& entity() const { return records.front().entity; }  // simple instances
  const std::vector<Value>& attributes() const { return records.front().attributes; }
  const Record* record(std::string_view entity) const;  // the partial record of that name, or null
  friend bool operator==(const Instance& a, const Instance& b) {
    return a.id == b.id && a.records == b.records && a.complex == b.complex;
  }
};

// HEADER section. Fields a file leaves as $ read as empty; other header entities are kept.
struct Header {
  std::vector<std::string> description;   // FILE_DESCRIPTION.description
  std::string implementation_level = "2;1";
  std::string name;                       // FILE_NAME.name
  std::string time_stamp;                 // empty: the writer stamps it (SOURCE_DATE_EPOCH, else now)
  std::vector<std::string> author{""};
  std::vector<std::string> organization{""};
  std::string preprocessor_version = "ncbridge";
  std::string originating_system = "ncbridge";
  std::string authorization;
  std::vector<std::string> schema;        // FILE_SCHEMA, e.g. {"MACHINING_SCHEMA", "MILLING_SCHEMA"}
  std::vector<Record> others;             // FILE_POPULATION, SECTION_LANGUAGE, ... as read
  friend bool operator==(const Header&, const Header&) = default;
};

class Graph {
 public:
  Header header;

  // Adds a simple instance with the next free id (one more than the largest id so far).
  InstanceId add(std::string_view entity, std::vector<Value> attributes);
  // Adds a complex instance; records are sorted by entity name as Part 21 requires.
  InstanceId add_complex(std::vector<Record> records);
  // Takes an id now for an instance filled later with set(); until then the writer refuses it.
  InstanceId reserve();
  void set(InstanceId id, std::string_view entity, std::vector<Value> attributes);
  // Inserts an instance with its own id (the reader); throws std::invalid_argument on a duplicate.
  void insert(Instance instance);

  const Instance* find(InstanceId id) const;
  Instance* find(InstanceId id);
  const Instance& at(InstanceId id) const;  // throws std::out_of_range
  bool contains(InstanceId id) const { return index_.count(id) != 0; }

  const std::vector<Instance>& instances() const { return instances_; }
  std::size_t size() const { return instances_.size(); }
  bool empty() const { return instances_.empty(); }

  // Ids of the instances whose (any) record has that entity name, in graph order.
  std::vector<InstanceId> ids_of(std::string_view entity) const;

  friend bool operator==(const Graph& a, const Graph& b) {
    return a.header == b.header && a.instances_ == b.instances_;
  }

 private:
  std::vector<Instance> instances_;
  std::unordered_map<InstanceId, std::size_t> index_;
  InstanceId next_id_ = 1;
};

}  // namespace ncbridge::step_writer::part21
