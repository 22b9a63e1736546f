#include "results/writer_attributes.h"

#include "core/error.h"
#include "core/input_file.h"
#include "results/h5_write.h"
#include "results/link_name.h"
#include "results/results_layout.h"
#include "results/sample_series.h"

namespace limber::results {

void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  check(try_write_string_attribute(object, name, abbreviated(value, kMaxAttributeText)) ? 0 : -1,
        "write a string attribute");
}

void write_int_attribute(hid_t object, const char* name, int value) {
  check(try_write_scalar_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value) ? 0 : -1,
        "write an integer attribute");
}

void write_doubles_attribute(hid_t object, const char* name, const double* values,
                             hsize_t count) {
  H5Handle space = checked(H5Screate_simple(1, &count, nullptr), "create a dataspace");
  H5Handle attribute = checked(
      H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      "create a real attribute");
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values), "write a real attribute");
}

void write_mass_properties(hid_t body, const MassProperties& m) {
  write_doubles_attribute(body, layout::body::kMassAttribute, &m.mass, 1);
  write_doubles_attribute(body, layout::body::kCenterOfMassAttribute, m.com_B.data(), 3);
  // Symmetric: column-major storage is the row-major one.
  write_doubles_attribute(body, layout::body::kInertiaAttribute, m.inertia_com_B.data(), 9);
}

H5Handle create_group(hid_t parent, const std::string& name) {
  return checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 "create a group");
}

void write_dataset(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& dims, const void* data) {
  check(try_write_dataset(parent, name, file_type, memory_type, dims, data) ? 0 : -1,
        "write a dataset");
}

namespace {

const char* shape_type_name(ShapeSpec::Type type) {
  switch (type) {
    case ShapeSpec::Type::kBox: return layout::shape::kBox;
    case ShapeSpec::Type::kCylinder: return layout::shape::kCylinder;
    case ShapeSpec::Type::kSphere: return layout::shape::kSphere;
  }
  LIMBER_DEMAND(false);
}

}  // namespace

void write_shapes(hid_t body_group, const std::vector<ShapeSpec>& shapes) {
  if (shapes.empty()) return;
  H5Handle group = create_group(body_group, layout::body::kShapes);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const ShapeSpec& shape = shapes[k];
    H5Handle shape_group = create_group(group.get(), std::to_string(k));
    write_string_attribute(shape_group.get(), layout::shape::kTypeAttribute, shape_type_name(shape.type));
    write_doubles_attribute(shape_group.get(), layout::shape::kSizeAttribute, shape.size.data(), 3);
    // Offset: position xyz then quaternion wxyz.
    const Eigen::Quaterniond& q = shape.offset_orientation;
    const double offset[7] = {shape.offset_position.x(), shape.offset_position.y(),
                              shape.offset_position.z(), q.w(), q.x(), q.y(), q.z()};
    write_doubles_attribute(shape_group.get(), layout::shape::kOffsetAttribute, offset, 7);
    write_doubles_attribute(shape_group.get(), layout::shape::kColorAttribute, shape.color.data(), 3);
  }
}

void write_string_dataset(hid_t parent, const char* name, const std::vector<std::string>& values) {
  check(try_write_string_dataset(parent, name, values) ? 0 : -1, "write a string dataset");
}

std::string new_link(std::set<std::string>& links, const std::string& name) {
  std::string link = link_name(name);
  LIMBER_DEMAND(links.insert(link).second);
  return link;
}

H5Handle create_named_group(hid_t parent, std::set<std::string>& links, const std::string& name) {
  H5Handle group = create_group(parent, new_link(links, name));
  write_string_attribute(group.get(), kNameAttribute, name);
  return group;
}

}  // namespace limber::results
