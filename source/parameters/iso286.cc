#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <array>
#include <cctype>
#include <map>
#include <vector>

namespace coaxfit
{
  namespace
  {
    /**
     * Upper limits (mm, inclusive) of the nominal size ranges of ISO 286-1
     * with the sub-ranges it uses for the fundamental deviations r to zc;
     * the first range is "up to 3 mm".
     */
    constexpr std::array<double, 25> sub_range_limits{
      {3,   6,   10,  14,  18,  24,  30,  40,  50,  65,  80,  100, 120,
       140, 160, 180, 200, 225, 250, 280, 315, 355, 400, 450, 500}};

    /** Upper limits of the main ranges (the standard tolerances). */
    constexpr std::array<double, 13> range_limits{
      {3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500}};

    /** IT5 to IT11 (micrometres) per main range, ISO 286-1 Table 1. */
    constexpr std::array<std::array<int, 13>, 7> it_table{{
      {{4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27}},
      {{6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40}},
      {{10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63}},
      {{14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97}},
      {{25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155}},
      {{40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250}},
      {{60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400}},
    }};

    using Row          = std::vector<int>;
    constexpr int none = -1; ///< not defined for this range

    /**
     * Lower deviations ei (micrometres) of the shafts m to zc, the same for
     * every grade, per sub-range; ISO 286-1 Table 3.
     */
    const std::map<std::string, Row> &
    fundamental_deviations()
    {
      static const std::map<std::string, Row> table{
        {"m", {2,  4,  6,  7,  7,  8,  8,  9,  9,  11, 11, 13, 13,
               15, 15, 15, 17, 17, 17, 20, 20, 21, 21, 23, 23}},
        {"n", {4,  8,  10, 12, 12, 15, 15, 17, 17, 20, 20, 23, 23,
               27, 27, 27, 31, 31, 31, 34, 34, 37, 37, 40, 40}},
        {"p", {6,  12, 15, 18, 18, 22, 22, 26, 26, 32, 32, 37, 37,
               43, 43, 43, 50, 50, 50, 56, 56, 62, 62, 68, 68}},
        {"r", {10, 15, 19, 23, 23, 28, 28, 34, 34,  41,  43,  51, 54,
               63, 65, 68, 77, 80, 84, 94, 98, 108, 114, 126, 132}},
        {"s", {14, 19,  23,  28,  28,  35,  35,  43,  43,  53,  59,  71, 79,
               92, 100, 108, 122, 130, 140, 158, 170, 190, 208, 232, 252}},
        {"t",
         {none, none, none, none, none, none, 41,  48,  54,  66,  75,  91, 104,
          122,  134,  146,  166,  180,  196,  218, 240, 268, 294, 330, 360}},
        {"u", {18,  23,  28,  33,  33,  41,  48,  60,  70,  87,  102, 124, 144,
               170, 190, 210, 236, 258, 284, 315, 350, 390, 435, 490, 540}},
        {"v",
         {none, none, none, none, 39,  47,  55,  68,  81,  102, 120, 146, 172,
          202,  228,  252,  284,  310, 340, 385, 425, 475, 530, 595, 660}},
        {"x", {20,  28,  34,  40,  45,  54,  64,  80,  97,  122, 146, 178, 210,
               248, 280, 310, 350, 385, 425, 475, 525, 590, 660, 740, 820}},
        {"y",
         {none, none, none, none, none, 63,  75,  94,  114, 144, 174, 214, 254,
          300,  340,  380,  425,  470,  520, 580, 650, 730, 820, 920, 1000}},
        {"z",
         {26,  35,  42,  50,  60,  73,  88,  112, 136, 172,  210,  258, 310,
          365, 415, 465, 520, 575, 640, 710, 790, 900, 1000, 1100, 1250}},
        {"za",
         {32,  42,  52,  64,  77,  98,  118, 148,  180,  226,  274,  335, 400,
          470, 535, 600, 670, 740, 820, 920, 1000, 1150, 1300, 1450, 1600}},
        {"zb",
         {40,  50,  67,  90,  108, 136,  160,  200,  242,  300,  360,  445, 525,
          620, 700, 780, 880, 960, 1050, 1200, 1300, 1500, 1650, 1850, 2100}},
        {"zc", {60,   80,   97,   130,  150,  188,  218,  274,  325,
                405,  480,  585,  690,  800,  900,  1000, 1150, 1250,
                1350, 1550, 1700, 1900, 2100, 2400, 2600}}};
      return table;
    }

    template <std::size_t n>
    std::size_t
    range_index(const std::array<double, n> &limits, const double diameter)
    {
      std::size_t i = 0;
      while (diameter > limits[i])
        ++i;
      return i;
    }

    const char *covered
      = "covered are hole-basis interference fits H5..H11 / m..zc grade "
        "5..11 (e.g. H7/s6), nominal diameters over 1 up to 500 mm";

    [[noreturn]] void
    refuse(const std::string &designation, const std::string &why)
    {
      throw InputError("parameter Fit/ISO fit = '" + designation + "': " + why
                       + "; " + covered + '.');
    }

    /** Split `letters digits` at the first digit; false if malformed. */
    bool
    split_class(const std::string &text,
                std::string       &letters,
                unsigned int      &grade)
    {
      std::size_t i = 0;
      while (i < text.size()
             && std::isalpha(static_cast<unsigned char>(text[i])))
        ++i;
      if (i == 0 || i == text.size() || text.size() - i > 2 || text[i] == '0')
        return false;
      for (std::size_t k = i; k < text.size(); ++k)
        if (!std::isdigit(static_cast<unsigned char>(text[k])))
          return false;
      letters = text.substr(0, i);
      grade   = std::stoi(text.substr(i));
      return true;
    }
  } // namespace



  int
  standard_tolerance(const unsigned int grade, const double diameter)
  {
    if (grade < 5 || grade > 11 || !(diameter > 0.) || diameter > 500.)
      throw InputError("IT" + std::to_string(grade) + " at " + number(diameter)
                       + " mm is not covered (IT5..IT11, up to 500 mm)");
    return it_table[grade - 5][range_index(range_limits, diameter)];
  }



  IsoFit
  iso_fit(const std::string &designation, const double diameter)
  {
    std::string compact;
    for (const char c : designation)
      if (!std::isspace(static_cast<unsigned char>(c)))
        compact += c;
    const auto slash = compact.find('/');
    if (slash == std::string::npos)
      refuse(designation, "expected HOLE/SHAFT such as H7/s6");
    std::string  hole, shaft;
    unsigned int hole_grade = 0, shaft_grade = 0;
    if (!split_class(compact.substr(0, slash), hole, hole_grade)
        || !split_class(compact.substr(slash + 1), shaft, shaft_grade))
      refuse(designation, "expected HOLE/SHAFT such as H7/s6");
    if (hole != "H")
      refuse(designation,
             hole == "h" ? "the hole's letter is upper case (H7/s6; a lower "
                           "case h is a shaft)" :
                           "only the hole-basis system (hole H) is covered");
    const auto &table = fundamental_deviations();
    const auto  row   = table.find(shaft);
    if (row == table.end())
      refuse(designation,
             "shaft '" + shaft
               + "' is not an interference fit class m..zc (lower case)");
    if (hole_grade < 5 || hole_grade > 11 || shaft_grade < 5
        || shaft_grade > 11)
      refuse(designation, "grades 5 to 11 are covered");
    if (!(diameter > 1.) || diameter > 500.)
      refuse(designation,
             "the joint diameter " + number(diameter)
               + " mm is outside 1 < D <= 500 mm");
    const int ei = row->second[range_index(sub_range_limits, diameter)];
    if (ei == none)
      refuse(designation,
             "ISO 286 defines no shaft '" + shaft + "' at this diameter ("
               + number(diameter) + " mm)");

    IsoFit fit;
    fit.name        = compact;
    fit.hole_lower  = 0;
    fit.hole_upper  = standard_tolerance(hole_grade, diameter);
    fit.shaft_lower = ei;
    fit.shaft_upper = ei + standard_tolerance(shaft_grade, diameter);
    return fit;
  }
} // namespace coaxfit
