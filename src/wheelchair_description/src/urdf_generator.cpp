#include <wheelchair_description/urdf_generator.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wheelchair_description {
namespace {

// Shapes the chair file does not describe (visual only; the model ignores them) [m].
constexpr double kWheelWidth = 0.06;      // 14" x 2.5" drive tyre
constexpr double kCasterRadius = 0.10;    // 8" caster wheel
constexpr double kCasterWidth = 0.05;     //
constexpr double kCasterInset = 0.12;     // caster axle ahead of the rear of the footprint
constexpr double kSeatHeight = 0.50;      // seat surface above the floor
constexpr double kBackrestHeight = 1.00;  // top of the backrest above the floor
constexpr double kBodyHeight = 1.00;      // height used for the body's roll/pitch inertia
constexpr double kLaserBox[3] = {0.155, 0.155, 0.185};   // SICK LMS1xx-class housing
constexpr double kRearLaserBox[3] = {0.10, 0.10, 0.15};  // nanoScan3-class safety scanner

/// Shortest text that reads back as `value`; sums of round numbers that differ from a
/// 1e-9 grid point by round-off only (0.06999999999999999) are written as that point (0.07).
std::string num(double value) {
  const double rounded = std::round(value * 1e9) / 1e9;
  if (std::abs(rounded - value) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(value))
    value = rounded;
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string xyz(double x, double y, double z) { return num(x) + " " + num(y) + " " + num(z); }

std::string origin(double x, double y, double z, double roll = 0.0, double yaw = 0.0) {
  return "<origin xyz=\"" + xyz(x, y, z) + "\" rpy=\"" + xyz(roll, 0.0, yaw) + "\"/>";
}

std::string box(double sx, double sy, double sz) {
  return "<geometry><box size=\"" + xyz(sx, sy, sz) + "\"/></geometry>";
}

std::string cylinder(double radius, double length) {
  return "<geometry><cylinder radius=\"" + num(radius) + "\" length=\"" + num(length) +
         "\"/></geometry>";
}

std::string visual(const std::string& placed, const std::string& geometry,
                   const std::string& material) {
  return "    <visual>" + placed + geometry + "<material name=\"" + material + "\"/></visual>\n";
}

/// A box between two corners (x0, y0, z0) and (x1, y1, z1) of its parent link.
std::string boxVisual(double x0, double y0, double z0, double x1, double y1, double z1,
                      const std::string& material) {
  return visual(origin(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)),
                box(x1 - x0, y1 - y0, z1 - z0), material);
}

std::string inertial(double mass, double ixx, double iyy, double izz) {
  return "    <inertial><mass value=\"" + num(mass) + "\"/><inertia ixx=\"" + num(ixx) +
         "\" ixy=\"0\" ixz=\"0\" iyy=\"" + num(iyy) + "\" iyz=\"0\" izz=\"" + num(izz) +
         "\"/></inertial>\n";
}

std::string joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& placed,
                  const std::string& extra = "") {
  return "  <joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/>" + placed + extra + "</joint>\n";
}

std::string link(const std::string& name, const std::string& body = "") {
  if (body.empty()) return "  <link name=\"" + name + "\"/>\n";
  return "  <link name=\"" + name + "\">\n" + body + "  </link>\n";
}

/// A wheel link: cylinder about its y axis (the axle), mass and inertia if given.
std::string wheelLink(const std::string& name, double radius, double width,
                      const std::string& inertia) {
  const std::string placed = origin(0.0, 0.0, 0.0, 1.5707963267948966);
  return link(name, visual(placed, cylinder(radius, width), "tyre") + "    <collision>" + placed +
                        cylinder(radius, width) + "</collision>\n" + inertia);
}

}  // namespace

std::string chairUrdf(const ChairParams& p) {
  const std::string problem = p.validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
  const double r = p.wheel_radius, b = p.half_track, d = p.cm_offset;
  double front = p.footprint.front().x(), rear = front;
  for (const auto& v : p.footprint) {
    front = std::max(front, v.x());
    rear = std::min(rear, v.x());
  }
  const double floor = -r;                            // the floor's height in base_link
  const double inner = b - 0.5 * kWheelWidth - 0.02;  // half-width between the drive wheels
  const double caster_x = rear + kCasterInset, caster_y = b - 0.5 * kWheelWidth;

  // The body + rider link sits at P_c (d behind P), so M_T and I_T are about its origin.
  const double w = p.width, l = p.length, h = kBodyHeight, mt = p.total_mass;
  std::string body =
      inertial(mt, mt * (w * w + h * h) / 12.0, mt * (l * l + h * h) / 12.0, p.body_inertia);
  // Shapes in the body link's coordinates: x_body = x_base_link + d.
  body += boxVisual(rear + d, -inner, floor + 0.10, 0.15 + d, inner, floor + 0.38, "frame");
  body += boxVisual(0.15 + d, -inner, floor + 0.05, front + d, inner, floor + 0.09, "frame");
  body += boxVisual(rear + 0.15 + d, -inner, floor + 0.38, 0.05 + d, inner, floor + kSeatHeight,
                    "seat");
  body += boxVisual(rear + 0.15 + d, -inner, floor + kSeatHeight, rear + 0.25 + d, inner,
                    floor + kBackrestHeight, "seat");
  body += "    <collision>" + origin(0.5 * (front + rear) + d, 0.0, floor + 0.5 * kBackrestHeight) +
          box(front - rear, w, kBackrestHeight) + "</collision>\n";

  const std::string wheel_inertia =
      inertial(p.wheel_mass, p.wheel_inertia_diam, p.wheel_inertia, p.wheel_inertia_diam);
  const std::string axle = "<axis xyz=\"0 1 0\"/>";

  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
         "<!-- Generated by wheelchair_description::chairUrdf from config/chair.yaml; do not "
         "edit:\n"
         "     rosrun wheelchair_description generate_urdf config/chair.yaml urdf/wheelchair.urdf "
         "-->\n"
         "<robot name=\"wheelchair\">\n"
         "  <material name=\"frame\"><color rgba=\"0.25 0.25 0.28 1\"/></material>\n"
         "  <material name=\"seat\"><color rgba=\"0.10 0.20 0.45 1\"/></material>\n"
         "  <material name=\"tyre\"><color rgba=\"0.05 0.05 0.05 1\"/></material>\n"
         "  <material name=\"sensor\"><color rgba=\"0.90 0.75 0.10 1\"/></material>\n";
  // base_link is the root: odom -> base_link (REP-105, DESIGN.md); base_footprint hangs
  // below it on the floor, so no frame ever has two parents.
  out << link(kBaseLinkFrame);
  out << link(kBaseFootprintFrame);
  out << joint("base_footprint_joint", "fixed", kBaseLinkFrame, kBaseFootprintFrame,
               origin(0.0, 0.0, -r));
  out << link("body", body);
  out << joint("body_joint", "fixed", kBaseLinkFrame, "body", origin(-d, 0.0, 0.0));
  out << wheelLink("left_wheel", r, kWheelWidth, wheel_inertia);
  out << joint(kLeftWheelJoint, "continuous", kBaseLinkFrame, "left_wheel", origin(0.0, b, 0.0),
               axle);
  out << wheelLink("right_wheel", r, kWheelWidth, wheel_inertia);
  out << joint(kRightWheelJoint, "continuous", kBaseLinkFrame, "right_wheel", origin(0.0, -b, 0.0),
               axle);
  for (const char* side : {"left", "right"}) {
    const std::string name = std::string(side) + "_caster";
    const double y = side[0] == 'l' ? caster_y : -caster_y;
    out << wheelLink(name, kCasterRadius, kCasterWidth, "");
    out << joint(name + "_joint", "fixed", kBaseLinkFrame, name,
                 origin(caster_x, y, floor + kCasterRadius));
  }
  out << link(kLaserFrame, visual(origin(0.0, 0.0, 0.0),
                                  box(kLaserBox[0], kLaserBox[1], kLaserBox[2]), "sensor"));
  out << joint("laser_joint", "fixed", kBaseLinkFrame, kLaserFrame,
               origin(p.laser_x, p.laser_y, p.laser_z, 0.0, p.laser_yaw));
  out << link(kRearLaserFrame,
              visual(origin(0.0, 0.0, 0.0),
                     box(kRearLaserBox[0], kRearLaserBox[1], kRearLaserBox[2]), "sensor"));
  out << joint("rear_laser_joint", "fixed", kBaseLinkFrame, kRearLaserFrame,
               origin(p.rear_laser_x, p.rear_laser_y, p.rear_laser_z, 0.0, p.rear_laser_yaw));
  out << "</robot>\n";
  return out.str();
}

}  // namespace wheelchair_description
