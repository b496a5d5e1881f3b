#include <coaxfit/io/result_writers.h>
#include <coaxfit/io/selection_writers.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

namespace coaxfit
{
  namespace selection_files
  {
    namespace
    {
      using Json = nlohmann::ordered_json;

      /** A length in mm, null if not finite. */
      Json
      length(const double x)
      {
        return std::isfinite(x) ? Json(x) : Json(nullptr);
      }

      Json
      governing(const FitSelection::End &end)
      {
        return {{"state", end.state}, {"criterion", end.criterion}};
      }

      /**
       * A safety; null where it is not finite (not known, or an unloaded
       * part), as summary.json of a run writes it.
       */
      Json
      safety(const double x)
      {
        return std::isfinite(x) ? Json(x) : Json(nullptr);
      }
    } // namespace



    std::string
    write_csv(const FitSelection &selection, const std::string &directory)
    {
      const std::string name = directory + "/fit_selection.csv";
      std::ofstream     csv  = open_result_file(name);
      if (selection.taper_fit())
        {
          // A taper has no ISO fit: the band of push-on distances.
          csv << "end,U_mm,push_on_distance_mm,governed_by,U_din_mm,"
                 "push_on_distance_din_mm,governed_by_din\n";
          const auto cell = [](const double x) {
            std::ostringstream c;
            if (std::isfinite(x))
              c << std::setprecision(8) << x;
            return c.str();
          };
          for (const auto &[end, fe, din] :
               {std::make_tuple("min", &selection.least, &selection.least_din),
                std::make_tuple("max",
                                &selection.largest,
                                &selection.largest_din)})
            csv << end << ',' << cell(fe->U) << ','
                << cell(selection.push_on(fe->U)) << ",\"" << fe->governed_by()
                << "\"," << cell(din->U) << ','
                << cell(selection.push_on(din->U)) << ",\""
                << din->governed_by() << "\"\n";
          close_result_file(csv, name);
          return "fit_selection.csv: the band of push-on distances (a taper "
                 "has no ISO fit)";
        }
      csv << "rank,fit,system,preferred,ES_um,EI_um,es_um,ei_um,U_min_um,"
             "U_max_um,inside_din_band\n";
      unsigned int rank = 0;
      for (const IsoFit &f : selection.fits)
        csv << ++rank << ',' << f.name << ','
            << (f.name[0] == 'H' ? "hole basis" : "shaft basis") << ','
            << (is_preferred_fit(f.name) ? 1 : 0) << ',' << f.hole_upper << ','
            << f.hole_lower << ',' << f.shaft_upper << ',' << f.shaft_lower
            << ',' << f.min_interference() << ',' << f.max_interference() << ','
            << (selection.inside_din_band(f) ? 1 : 0) << '\n';
      close_result_file(csv, name);
      return "fit_selection.csv: the " + std::to_string(selection.fits.size())
             + " ISO 286 fits inside [U_min, U_max], ranked";
    }



    std::string
    write_summary(const std::string  &case_name,
                  const FitSelection &selection,
                  const Verdict      &verdict,
                  const std::string  &first_fit,
                  const std::string  &directory)
    {
      Json fits = Json::array();
      for (const IsoFit &f : selection.fits)
        fits.push_back({{"fit", f.name},
                        {"U_min", f.min_interference() / 1000.},
                        {"U_max", f.max_interference() / 1000.},
                        {"inside_din_band", selection.inside_din_band(f)}});
      Json checks = Json::array();
      for (const FitSelection::Check &c : selection.checks)
        checks.push_back(
          {{"end", c.end},
           {"state", c.state},
           {"U", c.U},
           {"safety_slip", safety(c.safety_slip)},
           {"safety_yield_hub", safety(c.safety_yield_hub)},
           {"safety_yield_shaft", safety(c.safety_yield_shaft)},
           {"safety_fracture_hub", safety(c.safety_fracture_hub)},
           {"separated_length", c.separated_length},
           {"contact_lost", c.contact_lost},
           {"converged", c.converged}});
      Json j;
      j["case"] = case_name;
      j["mode"] = "select";
      j["selection"]
        = {{"U_min", length(selection.least.U)},
           {"U_max", length(selection.largest.U)},
           {"U_min_din", length(selection.least_din.U)},
           {"U_max_din", length(selection.largest_din.U)},
           {"governing",
            {{"U_min", governing(selection.least)},
             {"U_max", governing(selection.largest)},
             {"U_min_din", governing(selection.least_din)},
             {"U_max_din", governing(selection.largest_din)}}},
           {"fe_solves", selection.n_solves},
           {"checks", checks},
           {"notes", selection.notes},
           {"fits", fits},
           {"first_fit", first_fit},
           {"conflict", selection.conflict()},
           {"units",
            "mm, measured (drawing) diametral interference, smoothing loss "
            "included"}};
      if (selection.taper_fit())
        j["selection"]["push_on"]
          = {{"taper", selection.taper},
             {"a_min", length(selection.push_on(selection.least.U))},
             {"a_max", length(selection.push_on(selection.largest.U))},
             {"a_min_din", length(selection.push_on(selection.least_din.U))},
             {"a_max_din", length(selection.push_on(selection.largest_din.U))},
             {"units", "mm, push-on distance a = U / taper"}};
      if (selection.allowed_utilisation > 0.)
        {
          // The ends on the elastic-plastic load path (the hub may yield).
          Json plastic = Json::array();
          for (const FitSelection::PlasticCheck &c : selection.plastic_checks)
            plastic.push_back(
              {{"end", c.end},
               {"U", c.U},
               {"hub_utilisation", c.state.utilisation},
               {"hub_plastic_diameter", c.state.plastic_diameter},
               {"utilisation_stage", c.state.utilisation_stage},
               {"safety_slip", safety(c.safety_slip)},
               {"least_normal_force_stage", c.state.least_stage},
               {"joined_mean_pressure", c.state.joined_pressure},
               {"completed", c.state.completed}});
          j["selection"]["plastic"]
            = {{"allowed_utilisation", selection.allowed_utilisation},
               {"load_paths", selection.n_plastic_solves},
               {"checks", plastic}};
        }
      j["verdict"] = {{"ok", verdict.ok()}, {"failed", verdict.failed}};
      const std::string name = directory + "/summary.json";
      std::ofstream     out  = open_result_file(name);
      out << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
      close_result_file(out, name);
      return "summary.json: the selection and the verdict";
    }



    std::vector<std::string>
    file_names()
    {
      return {"fit_selection.csv", "summary.json"};
    }
  } // namespace selection_files
} // namespace coaxfit
