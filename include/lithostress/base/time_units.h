#ifndef lithostress_base_time_units_h
#define lithostress_base_time_units_h

namespace lithostress
{
  /** Seconds per Julian year (365.25 days): the year of every time entry
   * (Time stepping/Time unit) and of the constants yr and Myr of the loads'
   * Time factor. */
  constexpr double seconds_per_year = 365.25 * 24 * 3600;
} // namespace lithostress

#endif
