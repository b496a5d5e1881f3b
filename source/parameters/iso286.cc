#include <coaxfit/base/input_error.h>
#include <coaxfit/parameters/iso286.h>
#include <coaxfit/parameters/parameter_checks.h>

#include <array>
#include <cctype>
#include <limits>
#include <map>
#include <set>
#include <utility>
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

    /** IT4 to IT11 (micrometres) per main range, ISO 286-1 Table 1. */
    constexpr std::array<std::array<int, 13>, 8> it_table{{
      {{3, 4, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20}},
      {{4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27}},
      {{6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40}},
      {{10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63}},
      {{14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97}},
      {{25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155}},
      {{40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250}},
      {{60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400}},
    }};

    using Row = std::vector<int>;
    /** Not defined for this range (no deviation is this far off). */
    constexpr int none = std::numeric_limits<int>::min();

    /**
     * Lower deviations ei (micrometres) of the shafts k to zc per sub-range,
     * ISO 286-1 Table 3: the same for every grade, except k, whose row is
     * that of grades 4 to 7 (ei = 0 in the other grades).
     */
    const std::map<std::string, Row> &
    fundamental_deviations()
    {
      static const std::map<std::string, Row> table{
        {"k", {0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3,
               3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 5, 5}},
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
      = "covered are the interference and transition fits of the hole "
        "basis H5..H11 / js, k..zc and the shaft basis JS5..JS11, K5..K8, "
        "M5..M8, N5..N11, P..ZC 5..11 / h5..h11 (e.g. H7/s6, S7/h6), nominal diameters over "
        "1 up to 500 mm";

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

    /** @p text in lower case. */
    std::string
    lower(std::string text)
    {
      for (char &c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return text;
    }

    /**
     * The fundamental deviation ei of the shaft @p letter in grade
     * @p grade at @p diameter (micrometres); `none` where it is not
     * defined. The row must exist.
     */
    int
    shaft_deviation(const std::string &letter,
                    const unsigned int grade,
                    const double       diameter)
    {
      const int ei = fundamental_deviations().at(letter).at(
        range_index(sub_range_limits, diameter));
      // k: the tabulated row holds for grades 4 to 7 only.
      return letter == "k" && grade > 7 ? 0 : ei;
    }

    /**
     * The upper deviation ES of the hole @p letter (upper case K, M, N, P
     * to ZC) in grade @p grade at @p diameter, by ISO 286-1's rules for
     * holes from the shaft of the same letter: ES = -ei + Delta with
     * Delta = IT_grade - IT_(grade - 1) above 3 mm for K, M, N up to IT8
     * and for P to ZC up to IT7; ES = -ei for P to ZC above IT7; N above
     * IT8: ES = 0 (above 3 mm). The one exception of the table: M6 over
     * 250 up to 315 mm has ES = -9. `none` where it is not defined.
     */
    int
    hole_deviation(const std::string &letter,
                   const unsigned int grade,
                   const double       diameter)
    {
      const std::string shaft = lower(letter);
      const int         ei    = shaft_deviation(shaft, 7, diameter);
      if (ei == none)
        return none;
      const bool   above_3 = diameter > 3.;
      const double delta   = above_3 ?
                               standard_tolerance(grade, diameter)
                               - standard_tolerance(grade - 1, diameter) :
                               0;
      if (letter == "M" && grade == 6 && diameter > 250. && diameter <= 315.)
        return -9;
      if (letter == "N" && grade > 8)
        return above_3 ? 0 : -ei;
      if (letter == "K" || letter == "M" || letter == "N")
        return -ei + static_cast<int>(delta);
      return grade <= 7 ? -ei + static_cast<int>(delta) : -ei;
    }

    /**
     * The grades ISO 286-2 tabulates for the class letter @p letter (shaft
     * lower case, hole upper case), within 5 to 11: the candidates of a
     * selection stay among them (ISO 286-1's formulas would give any
     * grade). Typed from the tables' headings as commonly reproduced.
     */
    std::pair<unsigned int, unsigned int>
    tabulated_grades(const std::string &letter)
    {
      static const std::map<std::string, std::pair<unsigned int, unsigned int>>
        grades{{"js", {5, 11}}, {"JS", {5, 11}}, {"k", {5, 11}},
               {"m", {5, 9}},   {"n", {5, 9}},   {"p", {5, 10}},
               {"r", {5, 10}},  {"s", {5, 10}},  {"t", {5, 8}},
               {"u", {5, 9}},   {"v", {5, 8}},   {"x", {5, 10}},
               {"y", {6, 10}},  {"z", {6, 11}},  {"za", {6, 11}},
               {"zb", {7, 11}}, {"zc", {7, 11}}, {"K", {5, 8}},
               {"M", {5, 8}},   {"N", {5, 11}},  {"P", {5, 10}},
               {"R", {5, 10}},  {"S", {5, 10}},  {"T", {5, 8}},
               {"U", {5, 10}},  {"V", {5, 8}},   {"X", {5, 10}},
               {"Y", {6, 10}},  {"Z", {6, 11}},  {"ZA", {6, 11}},
               {"ZB", {7, 11}}, {"ZC", {7, 11}}};
      return grades.at(letter);
    }

    /**
     * Half the tolerance of the symmetric classes js and JS in grade
     * @p grade at @p diameter (micrometres): IT/2, with an odd IT of the
     * grades 7 to 11 first rounded down to the even value below (ISO
     * 286-2's tables, whole micrometres there; js5 and js6 keep halves).
     */
    double
    symmetric_deviation(const unsigned int grade, const double diameter)
    {
      int tolerance = standard_tolerance(grade, diameter);
      if (grade >= 7 && tolerance % 2 != 0)
        --tolerance;
      return 0.5 * tolerance;
    }

    /** The hole letters of the shaft basis: JS, K, M, N, P to ZC. */
    bool
    shaft_basis_hole(const std::string &letter)
    {
      return letter == "JS" || letter == "K" || letter == "M" || letter == "N"
             || (fundamental_deviations().count(lower(letter)) > 0
                 && letter != "k" && lower(letter) != letter
                 && lower(letter) >= "p");
    }
  } // namespace



  int
  standard_tolerance(const unsigned int grade, const double diameter)
  {
    if (grade < 4 || grade > 11 || !(diameter > 0.) || diameter > 500.)
      throw InputError("IT" + std::to_string(grade) + " at " + number(diameter)
                       + " mm is not covered (IT4..IT11, up to 500 mm)");
    return it_table[grade - 4][range_index(range_limits, diameter)];
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
    const bool hole_basis = hole == "H";
    if (!hole_basis && !shaft_basis_hole(hole))
      refuse(designation,
             lower(hole) == hole ?
               "the hole's letter is upper case (H7/s6; lower case is a "
               "shaft)" :
               "hole '" + hole
                 + "' is neither H (hole basis) nor an interference or "
                   "transition hole K, M, N, P..ZC (shaft basis)");
    if (!hole_basis && shaft != "h")
      refuse(designation,
             "the shaft basis pairs hole '" + hole
               + "' with a shaft h (such as " + hole + "7/h6)");
    const auto &table = fundamental_deviations();
    if (hole_basis && shaft != "js" && table.find(shaft) == table.end())
      refuse(designation,
             "shaft '" + shaft
               + "' is not an interference or transition class k..zc "
                 "(lower case)");
    if (hole_grade < 5 || hole_grade > 11 || shaft_grade < 5
        || shaft_grade > 11)
      refuse(designation, "grades 5 to 11 are covered");
    if (!hole_basis && (hole == "K" || hole == "M") && hole_grade > 8)
      refuse(designation, "holes K and M are covered in grades 5 to 8");
    if (!(diameter > 1.) || diameter > 500.)
      refuse(designation,
             "the joint diameter " + number(diameter)
               + " mm is outside 1 < D <= 500 mm");

    IsoFit fit;
    fit.name = compact;
    if (hole_basis && shaft == "js")
      {
        const double half = symmetric_deviation(shaft_grade, diameter);
        fit.hole_lower    = 0;
        fit.hole_upper    = standard_tolerance(hole_grade, diameter);
        fit.shaft_lower   = -half;
        fit.shaft_upper   = half;
      }
    else if (!hole_basis && hole == "JS")
      {
        const double half = symmetric_deviation(hole_grade, diameter);
        fit.hole_upper    = half;
        fit.hole_lower    = -half;
        fit.shaft_upper   = 0;
        fit.shaft_lower   = -standard_tolerance(shaft_grade, diameter);
      }
    else if (hole_basis)
      {
        const int ei = shaft_deviation(shaft, shaft_grade, diameter);
        if (ei == none)
          refuse(designation,
                 "ISO 286 defines no shaft '" + shaft + "' at this diameter ("
                   + number(diameter) + " mm)");
        fit.hole_lower  = 0;
        fit.hole_upper  = standard_tolerance(hole_grade, diameter);
        fit.shaft_lower = ei;
        fit.shaft_upper = ei + standard_tolerance(shaft_grade, diameter);
      }
    else
      {
        const int ES = hole_deviation(hole, hole_grade, diameter);
        if (ES == none)
          refuse(designation,
                 "ISO 286 defines no hole '" + hole + "' at this diameter ("
                   + number(diameter) + " mm)");
        fit.hole_upper  = ES;
        fit.hole_lower  = ES - standard_tolerance(hole_grade, diameter);
        fit.shaft_upper = 0;
        fit.shaft_lower = -standard_tolerance(shaft_grade, diameter);
      }
    return fit;
  }



  std::vector<IsoFit>
  candidate_fits(const double diameter)
  {
    std::vector<IsoFit> fits;
    if (!(diameter > 1.) || diameter > 500.)
      return fits;
    std::vector<std::string> letters{"js"};
    for (const auto &[letter, row] : fundamental_deviations())
      if (row[range_index(sub_range_limits, diameter)] != none)
        letters.push_back(letter);
    for (const std::string &letter : letters)
      {
        std::string hole_letter = letter;
        for (char &c : hole_letter)
          c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        for (unsigned int shaft_grade = 5; shaft_grade <= 8; ++shaft_grade)
          for (unsigned int hole_grade = shaft_grade;
               hole_grade <= shaft_grade + 1;
               ++hole_grade)
            {
              const auto shafts = tabulated_grades(letter);
              if (shaft_grade >= shafts.first && shaft_grade <= shafts.second)
                fits.push_back(iso_fit("H" + std::to_string(hole_grade) + "/"
                                         + letter + std::to_string(shaft_grade),
                                       diameter));
              const auto holes = tabulated_grades(hole_letter);
              if (hole_grade >= holes.first && hole_grade <= holes.second)
                fits.push_back(iso_fit(hole_letter + std::to_string(hole_grade)
                                         + "/h" + std::to_string(shaft_grade),
                                       diameter));
            }
      }
    return fits;
  }



  bool
  is_preferred_fit(const std::string &name)
  {
    // The interference and transition fits among the preferred fits:
    // transition H7/k6, H7/n6, interference H7/p6, H7/s6, H7/u6 and their
    // shaft-basis counterparts K7/h6, N7/h6, P7/h6, S7/h6, U7/h6 are the
    // preferred fits of the table of ISO 286-1 and ANSI B4.2-1978 as it is
    // commonly reproduced (e.g. in engineering handbooks' tables of
    // preferred metric fits); H7/r6 and R7/h6 are added from ISO 286-1:
    // 2010's figures of the hole-basis and shaft-basis systems, in which
    // r6 and R7 stand among the preferred classes. The standard's own text
    // was not at hand to check the last pair against.
    static const std::set<std::string> preferred{"H7/k6",
                                                 "H7/n6",
                                                 "H7/p6",
                                                 "H7/r6",
                                                 "H7/s6",
                                                 "H7/u6",
                                                 "K7/h6",
                                                 "N7/h6",
                                                 "P7/h6",
                                                 "R7/h6",
                                                 "S7/h6",
                                                 "U7/h6"};
    return preferred.count(name) > 0;
  }
} // namespace coaxfit
