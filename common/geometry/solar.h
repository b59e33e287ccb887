// Where the sun stands in the sky at a place and time: the sun light of a scene file (docs/scenes.md)
// and the shadow profiles of lessons 15 and 16 (Wallner, "Geometry of Real Time Shadows", section
// 8: the shadows a building casts over a day).
//
// The algorithm is Meeus's low-accuracy solar coordinates (Astronomical Algorithms, 2nd ed.,
// chapter 25: the sun's apparent longitude to 0.01 degree), his mean sidereal time (chapter 12,
// eq. 12.4) corrected to apparent by the nutation in longitude (chapter 22, its 0.5" series), and
// his horizontal coordinates (chapter 13). From there, as NREL's Solar Position Algorithm (Reda and
// Andreas 2004, sections 3.12-3.14): the parallax of a topocentric observer (elevation lowered by
// 8.794"/R cos e) and atmospheric refraction for a pressure and a temperature. Stated accuracy:
// 0.01 degree in elevation and, away from the zenith, in azimuth, for years 1950-2050 (Meeus's);
// the tests hold it against NREL's worked example and Meeus's example 25.a.
#pragma once
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace stencil {

// A civil date and local clock time. zoneHours is the time zone's offset from UTC in hours (+2 for
// Central European Summer Time, -7 for Mountain Standard Time); the UTC instant is the clock time
// minus it.
struct CivilTime {
  int year = 2000, month = 1, day = 1;  // Gregorian calendar
  int hour = 12, minute = 0;
  double second = 0.0;
  double zoneHours = 0.0;
};

// Julian Day of a UTC instant given as a civil time (Meeus chapter 7, Gregorian calendar): days
// since noon UT, 1 January 4713 BC (Julian calendar). The zone is taken out first.
double julianDay(const CivilTime& time);

// Whether a date exists in the Gregorian calendar (months of 28-31 days, leap years), and a
// clock time 0:00-23:59 with seconds in [0, 60) and a zone within -14 to +14 hours. The message
// says what is wrong, in a few words; empty when it is fine.
std::string civilTimeProblem(const CivilTime& time);

// The sun's geocentric apparent right ascension and declination (degrees, equator and equinox of
// date) and its distance (AU) at a Julian Ephemeris Day (Terrestrial Time), Meeus chapter 25.
struct SunEquatorial {
  double rightAscensionDeg = 0.0, declinationDeg = 0.0, distanceAu = 1.0;
  double apparentLongitudeDeg = 0.0, obliquityDeg = 0.0;
};
SunEquatorial sunEquatorial(double julianEphemerisDay);

// A place on the Earth and the air over it. Latitude in degrees, north positive, [-90, 90];
// longitude in degrees, east positive, [-180, 180]. pressureMillibar 0 turns refraction off.
struct SitePlace {
  double latitudeDeg = 0.0, longitudeDeg = 0.0;
  double pressureMillibar = 1010.0, temperatureC = 10.0;
  double deltaTSeconds = 69.0;  // TT - UT; 64-70 s for 2000-2025, and 1 s moves the sun 0.004 degree
};

// The sun seen from a place at a civil time: topocentric elevation above the horizon (refracted)
// and azimuth from north towards east, both in degrees; zenith = 90 - elevation.
struct SunPosition {
  double elevationDeg = 0.0, azimuthDeg = 0.0, zenithDeg = 90.0;
  double hourAngleDeg = 0.0;  // local, west positive
  SunEquatorial equatorial;
};
SunPosition sunPosition(const SitePlace& place, const CivilTime& time);

// The direction towards the sun in a scene's world: +y up, -z north, +x east (a site plan seen
// from above has north at the top of the picture), unit length.
glm::vec3 sunDirection(double elevationDeg, double azimuthDeg);

// "YYYY-MM-DD" and "HH:MM" or "HH:MM:SS" into a CivilTime (zone left at 0); nullopt when the text
// is not of that form (civilTimeProblem then says whether the numbers make sense).
std::optional<CivilTime> parseCivilTime(std::string_view date, std::string_view clock);

}  // namespace stencil
