#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <utility>

#include "geometry/solar.h"

namespace {

using namespace stencil;

// Meeus, Astronomical Algorithms (2nd ed.), example 25.a: the sun on 1992 October 13.0 TD.
TEST(SunEquatorial, MeeusExample25a) {
  const SunEquatorial s = sunEquatorial(2448908.5);
  EXPECT_NEAR(s.apparentLongitudeDeg, 199.90895, 5e-5);
  EXPECT_NEAR(s.obliquityDeg, 23.43999, 5e-5);
  EXPECT_NEAR(s.rightAscensionDeg, 198.38083, 5e-5);  // 13h 13m 31.4s
  EXPECT_NEAR(s.declinationDeg, -7.78507, 5e-5);      // -7 47' 06"
  EXPECT_NEAR(s.distanceAu, 0.99766, 5e-5);
}

// NREL's Solar Position Algorithm (Reda and Andreas 2004), its worked example (table A4.1 inputs,
// A5.1 results): Golden, Colorado, 17 October 2003 12:30:30 local time, zone -7, 820 mbar, 11 C,
// Delta T 67 s. SPA is good to 0.0003 degree; this algorithm claims 0.01.
TEST(SunPosition, NrelSpaWorkedExample) {
  const CivilTime time{2003, 10, 17, 12, 30, 30.0, -7.0};
  EXPECT_NEAR(julianDay(time), 2452930.312847, 1e-6);
  SitePlace golden;
  golden.latitudeDeg = 39.742476;
  golden.longitudeDeg = -105.1786;
  golden.pressureMillibar = 820.0;
  golden.temperatureC = 11.0;
  golden.deltaTSeconds = 67.0;
  const SunPosition p = sunPosition(golden, time);
  EXPECT_NEAR(p.zenithDeg, 50.11162, 0.01);
  EXPECT_NEAR(p.azimuthDeg, 194.34024, 0.01);
  EXPECT_NEAR(p.equatorial.rightAscensionDeg, 202.22741, 0.01);
  EXPECT_NEAR(p.equatorial.declinationDeg, -9.31434, 0.01);
}

// The highest the sun climbs in a day, found by golden-section search over the clock (UTC).
double noonElevation(double latitude, double longitude, int year, int month, int day) {
  SitePlace place;
  place.latitudeDeg = latitude;
  place.longitudeDeg = longitude;
  place.pressureMillibar = 0.0;  // no refraction: the geometric elevation
  const auto at = [&](double hours) {
    CivilTime t{year, month, day, 0, 0, 0.0, 0.0};
    const double seconds = hours * 3600.0;
    t.hour = static_cast<int>(seconds / 3600.0);
    t.minute = static_cast<int>((seconds - t.hour * 3600.0) / 60.0);
    t.second = seconds - t.hour * 3600.0 - t.minute * 60.0;
    return sunPosition(place, t).elevationDeg;
  };
  double lo = 0.0, hi = 23.99;
  for (int i = 0; i < 80; ++i) {
    const double a = lo + (hi - lo) * 0.382, b = lo + (hi - lo) * 0.618;
    (at(a) < at(b) ? lo : hi) = at(a) < at(b) ? a : b;
  }
  return at(0.5 * (lo + hi));
}

// At local noon the sun stands 90 - latitude + declination high: at an equinox the declination is
// 0, at the June solstice the obliquity (23.4393 degrees in 2024). The 2024 March equinox fell at
// 03:06 UTC on the 20th, when noon is at about 135 E; the June solstice at 20:51 UTC on the 20th,
// noon at about 135 W. Within 9 minutes of either the declination moves less than 0.002 degree.
TEST(SunPosition, EquinoxAndSolsticeNoonElevations) {
  for (double latitude : {48.2, 0.0, -33.9, 60.0}) {
    EXPECT_NEAR(noonElevation(latitude, 135.0, 2024, 3, 20), 90.0 - std::abs(latitude), 0.01) << latitude;
    const double june = 90.0 - std::abs(latitude - 23.4393);
    EXPECT_NEAR(noonElevation(latitude, -135.0, 2024, 6, 20), june, 0.01) << latitude;
  }
}

TEST(SunPosition, RisesInTheEastSetsInTheWestAndTheDirectionMatches) {
  SitePlace vienna;
  vienna.latitudeDeg = 48.2;
  vienna.longitudeDeg = 16.37;
  const SunPosition morning = sunPosition(vienna, {2025, 9, 18, 9, 0, 0.0, 2.0});
  const SunPosition evening = sunPosition(vienna, {2025, 9, 18, 17, 0, 0.0, 2.0});
  EXPECT_GT(morning.azimuthDeg, 90.0);  // south-east
  EXPECT_LT(morning.azimuthDeg, 180.0);
  EXPECT_GT(evening.azimuthDeg, 180.0);  // south-west
  EXPECT_LT(evening.azimuthDeg, 270.0);
  const glm::vec3 d = sunDirection(morning.elevationDeg, morning.azimuthDeg);
  EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
  EXPECT_GT(d.x, 0.0f);  // east is +x
  EXPECT_GT(d.z, 0.0f);  // south is +z
  EXPECT_NEAR(std::asin(d.y) * 180.0 / 3.14159265358979, morning.elevationDeg, 1e-4);
  EXPECT_EQ(sunDirection(0.0, 0.0), glm::vec3(0.0f, 0.0f, -1.0f));  // north is -z
}

TEST(CivilTime, ParsesAndChecks) {
  const auto t = parseCivilTime("2025-09-18", "09:30");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->year, 2025);
  EXPECT_EQ(t->month, 9);
  EXPECT_EQ(t->day, 18);
  EXPECT_EQ(t->hour, 9);
  EXPECT_EQ(t->minute, 30);
  EXPECT_TRUE(civilTimeProblem(*t).empty());
  EXPECT_TRUE(parseCivilTime("2025-09-18", "09:30:15"));
  for (const auto& [date, clock] : {std::pair{"2025-9-18", "09:30"},
                                    {"2025-09-18", "9:30"},
                                    {"2025/09/18", "09:30"},
                                    {"2025-09-18", "09:30:"},
                                    {"20x5-09-18", "09:30"},
                                    {"2025-09-18", "-9:30"}})
    EXPECT_FALSE(parseCivilTime(date, clock)) << date << " " << clock;
  for (const auto& [date, clock] : {std::pair{"2025-02-29", "12:00"},
                                    {"2025-13-01", "12:00"},
                                    {"2025-04-31", "12:00"},
                                    {"2025-09-18", "24:00"},
                                    {"2025-09-18", "12:60"},
                                    {"0000-01-01", "12:00"}})
    EXPECT_FALSE(civilTimeProblem(*parseCivilTime(date, clock)).empty()) << date << " " << clock;
  EXPECT_TRUE(civilTimeProblem(*parseCivilTime("2024-02-29", "23:59")).empty());  // a leap year
  CivilTime zone = *t;
  zone.zoneHours = 15.0;
  EXPECT_FALSE(civilTimeProblem(zone).empty());
}

}  // namespace
