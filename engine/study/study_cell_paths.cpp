// One cell of a table field as a varied parameter: "current.profile[1].speed" is the speed of the second row
// of the current profile (rows counted from 0, as the schema's messages count them). The row must exist in the
// base scenario (after "set"); a study changes that one value and leaves the table's other cells as they are.
#include <algorithm>
#include <charconv>

#include "study/study_design.hpp"

namespace maris::study::detail {

std::optional<TableCell> splitTableCell(const std::string& path, bool& malformed) {
  malformed = false;
  const auto open = path.find('[');
  if (open == std::string::npos) return std::nullopt;
  const auto close = path.find(']', open);
  TableCell cell;
  cell.table = path.substr(0, open);
  const char* first = path.data() + open + 1;
  const char* last = path.data() + (close == std::string::npos ? path.size() : close);
  const auto [end, error] = std::from_chars(first, last, cell.row);
  malformed = cell.table.empty() || close == std::string::npos || first == last || error != std::errc() ||
              end != last || close + 1 >= path.size() || path[close + 1] != '.';
  if (malformed) return std::nullopt;
  cell.column = path.substr(close + 2);
  return cell;
}

std::optional<ParamSpec> lookupTableCell(const SceneDefinition& scene, const Json& base, const std::string& path,
                                         const std::string& where, std::vector<FieldError>& errors, bool& is_cell) {
  bool malformed = false;
  const auto cell = splitTableCell(path, malformed);
  is_cell = cell.has_value() || malformed;
  if (malformed) {
    errors.push_back({where, "", "a cell of a table is written TABLE[ROW].COLUMN, rows counted from 0 "
                                 "(\"current.profile[1].speed\")"});
    return std::nullopt;
  }
  if (!cell) return std::nullopt;
  const ParamSpec* table = scene.schema.find(cell->table);
  if (!table || table->kind != ParamKind::Table) {
    std::vector<std::string> tables;
    for (const auto& f : scene.schema.fields)
      if (f.kind == ParamKind::Table) tables.push_back(f.path);
    const auto guess = didYouMean(cell->table, tables);
    errors.push_back({where, "", cell->table + " is not a table of scene '" + scene.name + "'" +
                                     (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
    return std::nullopt;
  }
  const ParamSpec* column = nullptr;
  std::vector<std::string> keys;
  for (const auto& c : table->columns) {
    keys.push_back(c.key());
    if (c.key() == cell->column) column = &c;
  }
  if (!column) {
    const auto guess = didYouMean(cell->column, keys);
    errors.push_back({where, "", cell->column + " is not a column of " + cell->table +
                                     (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
    return std::nullopt;
  }
  const Json* rows = findAtPath(base, cell->table);
  const std::size_t count = rows && rows->is_array() ? rows->size() : 0;
  if (cell->row >= count) {
    errors.push_back({where, "", "row " + std::to_string(cell->row) + " is not in the base scenario's " + cell->table +
                                     ", which has " + std::to_string(count) + (count == 1 ? " row" : " rows") +
                                     " (counted from 0; \"set\" may give the table more)"});
    return std::nullopt;
  }
  ParamSpec spec = *column;
  spec.path = tableCellPath(cell->table, cell->row, cell->column);
  spec.label = tableCellLabel(*table, *column, cell->row);
  return spec;
}

void setParameter(Json& parameters, const std::string& path, Json value) {
  bool malformed = false;
  const auto cell = splitTableCell(path, malformed);
  if (!cell) {
    setAtPath(parameters, path, std::move(value));
    return;
  }
  const Json* rows = findAtPath(parameters, cell->table);
  if (!rows || !rows->is_array() || cell->row >= rows->size() || !(*rows)[cell->row].is_object())
    throw InputError(path, "", "the table has no such row");  // checked when the study was read
  Json table = *rows;
  table[cell->row][cell->column] = std::move(value);
  setAtPath(parameters, cell->table, std::move(table));
}

}  // namespace maris::study::detail

namespace maris::study {

std::optional<TableCell> tableCell(const std::string& path) {
  bool malformed = false;
  return detail::splitTableCell(path, malformed);
}

std::string tableCellPath(const std::string& table, std::size_t row, const std::string& column) {
  return table + "[" + std::to_string(row) + "]." + column;
}

std::optional<ParamSpec> findStudyParameter(const SceneDefinition& scene, const Json& parameters,
                                            const std::string& path, std::string* why) {
  std::vector<FieldError> errors;
  auto spec = detail::lookupParameter(scene, parameters, path, path, errors);
  if (why) *why = errors.empty() ? std::string() : errors.front().message;
  return spec;
}

std::string studyParameterLabel(const Schema& schema, const std::string& path) {
  const std::string field = path.rfind("parameters.", 0) == 0 ? path.substr(11) : path;
  bool malformed = false;
  const auto cell = detail::splitTableCell(field, malformed);
  if (!cell) {
    const ParamSpec* spec = malformed ? nullptr : schema.find(field);
    return spec && spec->kind != ParamKind::Table ? parameterLabel(*spec) : std::string();
  }
  const ParamSpec* table = schema.find(cell->table);
  if (!table || table->kind != ParamKind::Table) return {};
  for (const auto& c : table->columns)
    if (c.key() == cell->column) return tableCellLabel(*table, c, cell->row);
  return {};
}

const Json* findParameterValue(const Json& parameters, const std::string& path) {
  const auto cell = tableCell(path);
  if (!cell) return findAtPath(parameters, path);
  const Json* rows = findAtPath(parameters, cell->table);
  if (!rows || !rows->is_array() || cell->row >= rows->size() || !(*rows)[cell->row].is_object()) return nullptr;
  const auto value = (*rows)[cell->row].find(cell->column);
  return value == (*rows)[cell->row].end() ? nullptr : &*value;
}

}  // namespace maris::study
