#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/base/names.h>
#include <hati/output/csv_file.h>
#include <hati/run/suite_plan.h>

#include <algorithm>

namespace hati
{
void SuiteParameters::declare_parameters(ParameterHandler &prm)
{
  prm.enter_subsection("Suite");
  prm.declare_entry(
      "Records",
      "",
      Patterns::Anything(),
      "Records of the suite, 'name: X-file, Y-file, Z-file; ...': the accelerograms "
      "along the global axes (as Loading/Accelerogram X, Y, Z; a component may be "
      "empty), name of letters, digits, '_', '-' and '.'. With Records, Variations or "
      "Scale factors other than 1 the file runs as a suite: one member run per record, "
      "scale factor and variation, each in output/<file>/<record>_s<scale>_<variation "
      "index>/, with suite.csv, suite_summary.json and suite_spectra.csv. Empty Records: "
      "the file's own accelerograms (record 'base'). 'artificial': the records of "
      "subsection Artificial records (art01, art02, ...).");
  prm.declare_entry(
      "Fundamental period",
      "0",
      Patterns::Double(0.),
      "The model's first period T1 (s) of the design spectrum check (suite_summary.json "
      "design_spectrum_check, over [0.2 T1, 2 T1]); 0: from a modal analysis of the "
      "model (its first mode of nonzero frequency, in <output>/modal/).");
  prm.declare_entry(
      "Scale factors",
      "1",
      Patterns::List(Patterns::Double(-100., 100.), 1),
      "Scale factors of the suite (-), each multiplying Loading/Accelerogram scale "
      "factor: every record is run at every factor; each factor once.");
  prm.declare_entry(
      "Variations",
      "",
      Patterns::Anything(),
      "Parameters varied over the suite, 'Entry/Path=v1|v2|...; ...' (e.g. "
      "'Model/Bridge crane/Trolley position=0.1|0.5|0.9'): every combination of the "
      "values is run with every record and scale factor; the variation index counts "
      "the combinations from 0, the first entry varying slowest. Each entry once; not "
      "Suite/*, Output/Output directory, Analysis/Type, Loading/Accelerogram scale "
      "factor (use Scale factors) nor, with Records, Loading/Accelerogram X|Y|Z. A "
      "suite has at most 10000 members (records x scale factors x variations).");
  prm.declare_entry(
      "Response spectrum comparison",
      "true",
      Patterns::Bool(),
      "With a subsection Design spectrum: also run the response-spectrum analysis of "
      "the model (the first member's parameters, Analysis/Type = response spectrum, "
      "the directions of the records, in <output>/response_spectrum/) and compare it "
      "with the suite's statistic (rsa_comparison.csv, rsa_comparison.png, "
      "suite_summary.json rsa_comparison).");
  prm.declare_entry(
      "Statistic",
      "",
      Patterns::Selection("|envelope|mean"),
      "Statistic over the records of each scale factor and variation in "
      "suite_summary.json and suite_spectra.csv: envelope (largest value) or mean; "
      "empty: mean from 7 records on, else envelope.");
  prm.leave_subsection();
}

namespace
{
std::vector<SuiteRecord> parse_records(const std::string &text)
{
  std::vector<SuiteRecord> records;
  for (const auto &item : Utilities::split_string_list(text, ';'))
  {
    const auto colon = item.find(':');
    AssertThrow(colon != std::string::npos,
                ExcMessage("Suite/Records: '" + printable(item) +
                           "' is not 'name: X-file, Y-file, Z-file'"));
    SuiteRecord r;
    r.name = Utilities::trim(item.substr(0, colon));
    check_name(r.name, "Suite/Records", "record");
    const std::string files = item.substr(colon + 1);
    std::vector<std::string> parts;
    std::string::size_type start = 0, comma;
    while ((comma = files.find(',', start)) != std::string::npos)
    {
      parts.push_back(Utilities::trim(files.substr(start, comma - start)));
      start = comma + 1;
    }
    parts.push_back(Utilities::trim(files.substr(start)));
    AssertThrow(
        parts.size() <= 3 &&
            std::any_of(parts.begin(), parts.end(), [](auto &p) { return !p.empty(); }),
        ExcMessage("Suite/Records: record '" + r.name +
                   "' needs one to three files 'X-file, Y-file, Z-file' (a "
                   "component may be empty), got '" +
                   printable(Utilities::trim(files)) + "'"));
    for (unsigned int d = 0; d < parts.size(); ++d)
      r.files[d] = parts[d];
    for (const auto &other : records)
      AssertThrow(
          other.name != r.name,
          ExcMessage("Suite/Records: the record name '" + r.name + "' is given twice"));
    records.push_back(r);
  }
  return records;
}

std::vector<SuiteVariation> parse_variations(const std::string &text)
{
  std::vector<SuiteVariation> variations;
  for (const auto &item : Utilities::split_string_list(text, ';'))
  {
    const auto eq = item.find('=');
    AssertThrow(eq != std::string::npos && eq > 0,
                ExcMessage("Suite/Variations: '" + printable(item) +
                           "' is not 'Entry/Path=v1|v2|...'"));
    SuiteVariation v;
    // the path as apply_override() reads it: its parts trimmed
    std::vector<std::string> parts;
    const std::string path = item.substr(0, eq);
    std::string::size_type start = 0, slash;
    while ((slash = path.find('/', start)) != std::string::npos)
    {
      parts.push_back(Utilities::trim(path.substr(start, slash - start)));
      start = slash + 1;
    }
    parts.push_back(Utilities::trim(path.substr(start)));
    for (const auto &p : parts)
      v.path += (v.path.empty() ? "" : "/") + p;
    v.values = Utilities::split_string_list(item.substr(eq + 1), '|');
    AssertThrow(!v.values.empty(),
                ExcMessage("Suite/Variations: '" + v.path + "' has no values"));
    for (const auto &other : variations)
      AssertThrow(other.path != v.path,
                  ExcMessage("Suite/Variations: the entry '" + v.path +
                             "' is given twice; give all its values in one list '" +
                             v.path + "=v1|v2|...'"));
    variations.push_back(v);
  }
  return variations;
}

/** Refuse a variation of an entry the suite sets for each member, or of the analysis. */
void check_variation_paths(const std::vector<SuiteVariation> &variations,
                           const bool with_records)
{
  for (const auto &v : variations)
  {
    const std::string head = "Suite/Variations: '" + v.path + "' ";
    AssertThrow(v.path.rfind("Suite/", 0) != 0 && v.path != "Suite",
                ExcMessage(head + "cannot be varied: subsection Suite describes the "
                                  "suite itself (each member runs without it)"));
    AssertThrow(v.path != "Output/Output directory",
                ExcMessage(head + "cannot be varied: each member writes into its own "
                                  "folder <Output directory>/<member>"));
    AssertThrow(v.path != "Loading/Accelerogram scale factor",
                ExcMessage(head + "cannot be varied: give the factors in Suite/Scale "
                                  "factors (each multiplies the file's Loading/"
                                  "Accelerogram scale factor)"));
    AssertThrow(v.path != "Analysis/Type",
                ExcMessage(head + "cannot be varied: a suite runs transient analyses"));
    for (const char axis : {'X', 'Y', 'Z'})
      AssertThrow(!with_records || v.path != std::string("Loading/Accelerogram ") + axis,
                  ExcMessage(head + "cannot be varied with Suite/Records: each "
                                    "record sets the accelerograms of its members"));
  }
}
} // namespace

void SuiteParameters::parse_parameters(ParameterHandler &prm,
                                       const std::vector<SuiteRecord> &artificial)
{
  prm.enter_subsection("Suite");
  const std::string records_text = prm.get("Records");
  const std::string scales_text = prm.get("Scale factors");
  const std::string variations_text = prm.get("Variations");
  statistic = prm.get("Statistic");
  response_spectrum_comparison = prm.get_bool("Response spectrum comparison");
  fundamental_period = prm.get_double("Fundamental period");
  prm.leave_subsection();
  if (Utilities::trim(records_text) == "artificial")
  {
    AssertThrow(!artificial.empty(),
                ExcMessage("Suite/Records: 'artificial' needs records: Artificial "
                           "records/Number is 0"));
    records = artificial;
  }
  else
    records = parse_records(records_text);
  scale_factors = Utilities::string_to_double(Utilities::split_string_list(scales_text));
  // two equal factors (1, 1.0) would be one member folder run twice
  for (unsigned int i = 0; i < scale_factors.size(); ++i)
    for (unsigned int j = 0; j < i; ++j)
      AssertThrow(scale_factors[i] != scale_factors[j],
                  ExcMessage("Suite/Scale factors: the factor " +
                             shortest_number(scale_factors[i]) + " is given twice ('" +
                             Utilities::trim(scales_text) + "'); give each factor once"));
  variations = parse_variations(variations_text);
  check_variation_paths(variations, !records.empty());
  // the count in floating point: it cannot wrap
  double count = std::max<double>(records.size(), 1) * scale_factors.size();
  for (const auto &v : variations)
    count *= v.values.size();
  AssertThrow(
      count <= max_suite_members,
      ExcMessage("Suite: " + std::to_string(std::max<std::size_t>(records.size(), 1)) +
                 " records x " + std::to_string(scale_factors.size()) +
                 " scale factors x " +
                 shortest_number(count / std::max<double>(records.size(), 1) /
                                 scale_factors.size()) +
                 " variations = " + shortest_number(count) + " members, at most " +
                 std::to_string(max_suite_members) +
                 " (split the suite into several parameter files)"));
}

unsigned int SuiteParameters::n_variations() const
{
  unsigned int n = 1;
  for (const auto &v : variations)
    n *= v.values.size();
  return n;
}

unsigned int SuiteParameters::n_members() const
{
  return std::max<unsigned int>(records.size(), 1) * scale_factors.size() *
         n_variations();
}

bool SuiteParameters::active() const
{
  return !records.empty() || !variations.empty() || scale_factors.size() != 1 ||
         scale_factors[0] != 1.;
}

std::string SuiteParameters::effective_statistic() const
{
  if (!statistic.empty())
    return statistic;
  return records.size() >= 7 ? "mean" : "envelope";
}

std::vector<SuiteMember> plan_suite(const SuiteParameters &suite,
                                    const std::string &folder,
                                    const double base_scale)
{
  std::vector<SuiteRecord> records = suite.records;
  if (records.empty())
    records.push_back({"base", {}});
  const unsigned int n_variations = suite.n_variations();
  std::vector<SuiteMember> members;
  members.reserve(suite.n_members());
  for (const auto &record : records)
    for (const double scale : suite.scale_factors)
      for (unsigned int k = 0; k < n_variations; ++k)
      {
        SuiteMember m;
        m.index = members.size();
        m.record = record.name;
        m.scale = scale;
        m.variation = k;
        m.name = record.name + "_s" + shortest_number(scale) + "_" + std::to_string(k);
        constexpr std::size_t max_name = 255; // NAME_MAX of Linux file systems
        AssertThrow(m.name.size() <= max_name,
                    ExcMessage("Suite/Records: the record name '" +
                               record.name.substr(0, 40) + "...' (" +
                               std::to_string(record.name.size()) +
                               " characters) is too long: its member folder '" +
                               m.name.substr(0, 40) + "...' would have " +
                               std::to_string(m.name.size()) + " characters, at most " +
                               std::to_string(max_name)));
        if (!suite.records.empty())
          for (unsigned int d = 0; d < 3; ++d)
            m.overrides.push_back(std::string("Loading/Accelerogram ") + "XYZ"[d] + "=" +
                                  record.files[d]);
        m.overrides.push_back("Loading/Accelerogram scale factor=" +
                              shortest_number(base_scale * scale));
        // the first variation varies slowest
        unsigned int rest = k, stride = n_variations;
        for (const auto &v : suite.variations)
        {
          stride /= v.values.size();
          const std::string &value = v.values[rest / stride];
          rest %= stride;
          m.variation_values.push_back(value);
          m.overrides.push_back(v.path + "=" + value);
        }
        m.overrides.insert(m.overrides.end(),
                           {"Output/Output directory=" + folder + "/" + m.name,
                            "Suite/Records=",
                            "Suite/Scale factors=1",
                            "Suite/Variations=",
                            "Suite/Statistic=",
                            "Suite/Fundamental period=0",
                            // the target is the suite's, not a member's: a new
                            // target reuses the members
                            "Design spectrum/Type=none",
                            "Design spectrum/Ground type=C",
                            "Design spectrum/Peak ground acceleration=0",
                            "Design spectrum/Damping ratio=0.05",
                            "Design spectrum/Vertical=true",
                            "Design spectrum/Table file=",
                            "Design spectrum/Period range=0.02, 4"});
        members.push_back(m);
      }
  return members;
}
} // namespace hati
