#include "geometry/solar.h"

#include <charconv>
#include <cmath>
#include <numbers>

namespace stencil {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double reduce360(double degrees) {
  const double r = std::fmod(degrees, 360.0);
  return r < 0.0 ? r + 360.0 : r;
}

bool leapYear(int y) {
  return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

int daysInMonth(int y, int m) {
  static constexpr int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && leapYear(y) ? 29 : days[m - 1];
}

}  // namespace

std::string civilTimeProblem(const CivilTime& t) {
  if (t.year < 1 || t.year > 9999) return "the year must be 1 to 9999";
  if (t.month < 1 || t.month > 12) return "the month must be 1 to 12";
  if (t.day < 1 || t.day > daysInMonth(t.year, t.month))
    return "day " + std::to_string(t.day) + " does not exist in month " + std::to_string(t.month) + " of " +
           std::to_string(t.year);
  if (t.hour < 0 || t.hour > 23 || t.minute < 0 || t.minute > 59 || !(t.second >= 0.0 && t.second < 60.0))
    return "the time must be 00:00 to 23:59:59";
  if (!(t.zoneHours >= -14.0 && t.zoneHours <= 14.0))
    return "the time zone must be -14 to +14 hours from UTC";
  return {};
}

double julianDay(const CivilTime& t) {
  // Meeus (7.1), the day with its fraction in UT.
  int y = t.year, m = t.month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const int a = y / 100, b = 2 - a + a / 4;
  const double dayFraction = (t.hour + t.minute / 60.0 + t.second / 3600.0 - t.zoneHours) / 24.0;
  return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + t.day + dayFraction + b - 1524.5;
}

SunEquatorial sunEquatorial(double jde) {
  const double T = (jde - 2451545.0) / 36525.0;  // Julian centuries from J2000.0
  // Meeus (25.2)-(25.4): geometric mean longitude, mean anomaly, eccentricity of the Earth's orbit.
  const double L0 = reduce360(280.46646 + T * (36000.76983 + T * 0.0003032));
  const double M = reduce360(357.52911 + T * (35999.05029 - T * 0.0001537));
  const double e = 0.016708634 - T * (0.000042037 + T * 0.0000001267);
  const double Mr = M * kDeg;
  // The equation of the centre, the true longitude and anomaly, the radius vector (25.5).
  const double C = (1.914602 - T * (0.004817 + T * 0.000014)) * std::sin(Mr) +
                   (0.019993 - T * 0.000101) * std::sin(2.0 * Mr) + 0.000289 * std::sin(3.0 * Mr);
  const double trueLongitude = L0 + C, v = (M + C) * kDeg;
  SunEquatorial s;
  s.distanceAu = 1.000001018 * (1.0 - e * e) / (1.0 + e * std::cos(v));
  // Apparent longitude: nutation and aberration, and the obliquity corrected likewise (25.8).
  const double omega = (125.04 - 1934.136 * T) * kDeg;
  s.apparentLongitudeDeg = reduce360(trueLongitude - 0.00569 - 0.00478 * std::sin(omega));
  const double epsilon0 =
      23.0 + (26.0 + (21.448 - T * (46.8150 + T * (0.00059 - T * 0.001813))) / 60.0) / 60.0;
  s.obliquityDeg = epsilon0 + 0.00256 * std::cos(omega);
  const double lambda = s.apparentLongitudeDeg * kDeg, eps = s.obliquityDeg * kDeg;
  // (25.6), (25.7).
  s.rightAscensionDeg = reduce360(std::atan2(std::cos(eps) * std::sin(lambda), std::cos(lambda)) / kDeg);
  s.declinationDeg = std::asin(std::sin(eps) * std::sin(lambda)) / kDeg;
  return s;
}

SunPosition sunPosition(const SitePlace& place, const CivilTime& time) {
  const double jd = julianDay(time);
  SunPosition p;
  p.equatorial = sunEquatorial(jd + place.deltaTSeconds / 86400.0);
  // Greenwich mean sidereal time (12.4), made apparent by the nutation in longitude times cos(eps)
  // (chapter 12; the nutation from chapter 22's low-accuracy series).
  const double T = (jd - 2451545.0) / 36525.0;
  const double theta0 =
      280.46061837 + 360.98564736629 * (jd - 2451545.0) + T * T * (0.000387933 - T / 38710000.0);
  const double omega = (125.04452 - 1934.136261 * T) * kDeg;
  const double Lsun = (280.4665 + 36000.7698 * T) * kDeg, Lmoon = (218.3165 + 481267.8813 * T) * kDeg;
  const double deltaPsiArcsec = -17.20 * std::sin(omega) - 1.32 * std::sin(2.0 * Lsun) -
                                0.23 * std::sin(2.0 * Lmoon) + 0.21 * std::sin(2.0 * omega);
  const double theta = theta0 + deltaPsiArcsec / 3600.0 * std::cos(p.equatorial.obliquityDeg * kDeg);
  // Local hour angle, west positive (Meeus chapter 13: H = theta - L - alpha, L west positive).
  p.hourAngleDeg = reduce360(theta + place.longitudeDeg - p.equatorial.rightAscensionDeg);
  const double H = p.hourAngleDeg * kDeg, phi = place.latitudeDeg * kDeg,
               delta = p.equatorial.declinationDeg * kDeg;
  // (13.6), with the azimuth turned from south-based to north-based, east positive.
  const double sinE = std::sin(phi) * std::sin(delta) + std::cos(phi) * std::cos(delta) * std::cos(H);
  double elevation = std::asin(std::fmax(-1.0, std::fmin(1.0, sinE))) / kDeg;
  p.azimuthDeg = reduce360(
      std::atan2(std::sin(H), std::cos(H) * std::sin(phi) - std::tan(delta) * std::cos(phi)) / kDeg + 180.0);
  // Parallax at sea level (SPA 3.12: the equatorial horizontal parallax 8.794" / R).
  elevation -= 8.794 / 3600.0 / p.equatorial.distanceAu * std::cos(elevation * kDeg);
  // Refraction (SPA 3.14.1), only while the sun's upper limb is above the horizon.
  if (place.pressureMillibar > 0.0 && elevation >= -(0.26667 + 0.5667))
    elevation += place.pressureMillibar / 1010.0 * 283.0 / (273.0 + place.temperatureC) * 1.02 /
                 (60.0 * std::tan((elevation + 10.3 / (elevation + 5.11)) * kDeg));
  p.elevationDeg = elevation;
  p.zenithDeg = 90.0 - elevation;
  return p;
}

glm::vec3 sunDirection(double elevationDeg, double azimuthDeg) {
  const double e = elevationDeg * kDeg, a = azimuthDeg * kDeg;
  return glm::vec3(static_cast<float>(std::cos(e) * std::sin(a)), static_cast<float>(std::sin(e)),
                   static_cast<float>(-std::cos(e) * std::cos(a)));
}

std::optional<CivilTime> parseCivilTime(std::string_view date, std::string_view clock) {
  const auto whole = [](std::string_view s, int& value) {
    if (s.empty() || s.size() > 4) return false;
    for (char c : s)
      if (c < '0' || c > '9') return false;
    std::from_chars(s.data(), s.data() + s.size(), value);
    return true;
  };
  CivilTime t;
  if (date.size() != 10 || date[4] != '-' || date[7] != '-' || !whole(date.substr(0, 4), t.year) ||
      !whole(date.substr(5, 2), t.month) || !whole(date.substr(8, 2), t.day))
    return std::nullopt;
  int seconds = 0;
  if (!(clock.size() == 5 || (clock.size() == 8 && clock[5] == ':')) || clock[2] != ':' ||
      !whole(clock.substr(0, 2), t.hour) || !whole(clock.substr(3, 2), t.minute) ||
      (clock.size() == 8 && !whole(clock.substr(6, 2), seconds)))
    return std::nullopt;
  t.second = seconds;
  return t;
}

}  // namespace stencil
