#include "plots/reference_data.hpp"

#include "core/table_reader.hpp"

namespace maris::ui {

Table tableFromCsv(const std::string& text, const std::string& name) {
  TableSpec spec{"reference data", name, "a names row, an optional units row, then numbers: x and one or more y"};
  spec.names = TableSpec::Names::required;
  spec.min_columns = 2;
  refuseForeignFormat(text, spec);
  const TextTable parsed = parseTable(text, spec);
  if (parsed.rows.empty()) throw InputError({tableError(spec, 0, "the file has names but no rows of numbers")});
  Table table;
  table.name = name;
  table.title = name;
  for (std::size_t c = 0; c < parsed.columns(); ++c) {
    std::vector<double> values;
    for (const auto& row : parsed.rows) values.push_back(*row.cells[c]);
    table.add(parsed.names[c], parsed.units[c], std::move(values));
  }
  return table;
}

ReferenceColumns matchReferenceColumns(const Table& reference, const PlotSpec& spec) {
  ReferenceColumns out;
  if (reference.columns.size() < 2) return out;
  out.x = reference.find(spec.x);
  if (!out.x) out.x = &reference.columns.front();
  for (const auto& name : spec.y)
    if (const Column* c = reference.find(name); c && c != out.x) out.y.push_back(c);
  if (out.y.empty())
    for (const auto& c : reference.columns)
      if (&c != out.x) out.y.push_back(&c);
  return out;
}

std::vector<std::string> referenceUnitMismatches(const Table& reference, const Results& results, const PlotSpec& spec) {
  std::vector<std::string> notes;
  const Table* table = results.findTable(spec.table);
  if (!table) return notes;
  const ReferenceColumns match = matchReferenceColumns(reference, spec);
  auto check = [&](const Column* ref, const Column* plotted) {
    if (!ref || !plotted || ref->unit.empty() || plotted->unit.empty() || ref->unit == plotted->unit) return;
    notes.push_back("column '" + ref->name + "' is in " + ref->unit + ", the plot's axis in " + plotted->unit +
                    " (drawn as given, not converted)");
  };
  check(match.x, table->find(spec.x));
  const Column* first_y = spec.y.empty() ? nullptr : table->find(spec.y.front());
  for (const Column* y : match.y) check(y, table->find(y->name) ? table->find(y->name) : first_y);
  return notes;
}

}  // namespace maris::ui
