// The EXPRESS parser on the ISO 14649 schema: attribute lists checked by hand against the text.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/express_schema.hpp"

namespace fs = std::filesystem;
using namespace ncbridge::step_writer::express;

namespace {

const Schema& iso14649() {
  static const Schema schema =
      Schema::parse_file(fs::path(NCBRIDGE_SHARED_DIR) / "reference/iso14649/combined_schema_iso14649_only.exp");
  return schema;
}

std::vector<std::string> names_of(const std::vector<InstanceAttribute>& attributes) {
  std::vector<std::string> names;
  for (const auto& a : attributes) names.push_back(a.attribute->name);
  return names;
}

}  // namespace

TEST(ExpressSchema, ReadsTheWholeIso14649Schema) {
  const Schema& s = iso14649();
  EXPECT_EQ(s.name(), "COMBINED_SCHEMA");
  EXPECT_EQ(s.entities().size(), 422u);  // grep -c '^ *ENTITY' on the file
  EXPECT_GT(s.types().size(), 50u);
}

TEST(ExpressSchema, MachiningWorkingstepInheritsIdAndSecurityPlane) {
  auto attributes = iso14649().instance_attributes("machining_workingstep");
  EXPECT_EQ(names_of(attributes),
            (std::vector<std::string>{"its_id", "its_secplane", "its_feature", "its_operation", "its_effect"}));
  EXPECT_EQ(attributes[0].owner, "EXECUTABLE");
  EXPECT_EQ(attributes[1].owner, "WORKINGSTEP");
  EXPECT_EQ(attributes[2].attribute->type.kind, Type::Kind::Named);
  EXPECT_EQ(attributes[2].attribute->type.name, "MANUFACTURING_FEATURE");
  EXPECT_FALSE(attributes[3].attribute->optional);
  EXPECT_TRUE(attributes[4].attribute->optional);
  EXPECT_TRUE(iso14649().entity("WORKINGSTEP")->abstract);
  EXPECT_FALSE(iso14649().entity("MACHINING_WORKINGSTEP")->abstract);
}

TEST(ExpressSchema, PlanarFaceHasNineAttributesEndingWithItsBoss) {
  auto attributes = iso14649().instance_attributes("PLANAR_FACE");
  EXPECT_EQ(names_of(attributes),
            (std::vector<std::string>{"its_id", "its_workpiece", "its_operations", "feature_placement",
                                      "depth", "course_of_travel", "removal_boundary", "face_boundary", "its_boss"}));
  const Type& operations = attributes[2].attribute->type;
  EXPECT_EQ(operations.kind, Type::Kind::Aggregate);
  EXPECT_EQ(operations.aggregate, Type::Aggregate::Set);
  EXPECT_EQ(operations.lower, 0);
  EXPECT_FALSE(operations.upper.has_value());
  EXPECT_EQ(operations.element.at(0).name, "MACHINING_OPERATION");
  EXPECT_TRUE(attributes[7].attribute->optional);
  EXPECT_EQ(attributes[8].attribute->type.to_string(), "SET [0:?] OF BOSS");
}

TEST(ExpressSchema, CartesianPointAndItsBoundedList) {
  auto attributes = iso14649().instance_attributes("CARTESIAN_POINT");
  EXPECT_EQ(names_of(attributes), (std::vector<std::string>{"name", "coordinates"}));
  const Type& coordinates = attributes[1].attribute->type;
  EXPECT_EQ(coordinates.aggregate, Type::Aggregate::List);
  EXPECT_EQ(coordinates.lower, 1);
  EXPECT_EQ(coordinates.upper, 3);
  EXPECT_EQ(coordinates.element.at(0).name, "LENGTH_MEASURE");
  EXPECT_TRUE(iso14649().is_subtype_of("CARTESIAN_POINT", "GEOMETRIC_REPRESENTATION_ITEM"));
  EXPECT_FALSE(iso14649().is_subtype_of("CARTESIAN_POINT", "DIRECTION"));
}

TEST(ExpressSchema, OperationsStartWithToolpathAndToolDirection) {
  auto attributes = iso14649().instance_attributes("PLANE_FINISH_MILLING");
  ASSERT_EQ(attributes.size(), 14u);  // notes/iso14649.md
  EXPECT_EQ(attributes[0].attribute->name, "its_toolpath");
  EXPECT_EQ(attributes[1].attribute->name, "its_tool_direction");
  EXPECT_EQ(attributes[2].attribute->name, "its_id");
  EXPECT_EQ(iso14649().instance_attributes("DRILLING").size(), 14u);
  EXPECT_EQ(iso14649().instance_attributes("CLOSED_POCKET").size(), 11u);
  EXPECT_EQ(iso14649().instance_attributes("CLOSED_POCKET")[5].attribute->name, "its_boss");
}

TEST(ExpressSchema, SelectsEnumerationsAndDefinedTypes) {
  const DefinedType* length = iso14649().type("length_measure");
  ASSERT_NE(length, nullptr);
  EXPECT_EQ(length->underlying.kind, Type::Kind::Real);
  const DefinedType* strategy = iso14649().type("CUTMODE_TYPE");
  ASSERT_NE(strategy, nullptr);
  EXPECT_EQ(strategy->underlying.kind, Type::Kind::Enumeration);
  EXPECT_EQ(strategy->underlying.items, (std::vector<std::string>{"CLIMB", "CONVENTIONAL"}));
  const DefinedType* vector_or_direction = iso14649().type("VECTOR_OR_DIRECTION");
  ASSERT_NE(vector_or_direction, nullptr);
  EXPECT_EQ(vector_or_direction->underlying.kind, Type::Kind::Select);
  EXPECT_EQ(vector_or_direction->underlying.items, (std::vector<std::string>{"vector", "direction"}));
}

TEST(ExpressSchema, MultipleSupertypesDerivedAndInverseAttributes) {
  const char* text = R"(SCHEMA tiny;
    TYPE ratio = REAL; WHERE wr1: SELF >= 0; END_TYPE;
    (* a (* nested *) remark *)
    ENTITY a ABSTRACT SUPERTYPE; x : INTEGER; -- tail remark
    END_ENTITY;
    ENTITY b SUBTYPE OF (a); y, z : OPTIONAL LIST [2:?] OF ratio; END_ENTITY;
    ENTITY c SUBTYPE OF (a); w : STRING; DERIVE half : REAL := x / 2; INVERSE users : SET OF d FOR used; END_ENTITY;
    ENTITY d SUBTYPE OF (b, c); used : c; DERIVE SELF\a.x : INTEGER := 1; WHERE ok: TRUE; END_ENTITY;
    FUNCTION f(q : INTEGER) : INTEGER; RETURN (q); END_FUNCTION;
    END_SCHEMA;)";
  Schema s = Schema::parse(text, "tiny.exp");
  auto attributes = s.instance_attributes("D");
  EXPECT_EQ(names_of(attributes), (std::vector<std::string>{"x", "y", "z", "w", "used"}));
  EXPECT_TRUE(attributes[0].derived);
  EXPECT_FALSE(attributes[1].derived);
  EXPECT_TRUE(attributes[2].attribute->optional);
  EXPECT_EQ(attributes[2].attribute->type.lower, 2);
  EXPECT_EQ(s.instance_attributes("C").size(), 2u);  // half and users are not instantiated
  EXPECT_TRUE(s.entity("a")->abstract);
  EXPECT_TRUE(s.is_subtype_of("D", "A"));
}

TEST(ExpressSchema, ReportsBrokenSchemasWithAPlace) {
  try {
    Schema::parse("SCHEMA s;\nENTITY e;\n  x INTEGER;\nEND_ENTITY;\n", "bad.exp");
    ADD_FAILURE() << "accepted";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().line, 3u);
  }
  EXPECT_THROW(Schema::parse("ENTITY e; x : INTEGER;", "cut.exp"), ncbridge::InputError);
  EXPECT_THROW(Schema::parse("(* never closed", "r.exp"), ncbridge::InputError);
}
