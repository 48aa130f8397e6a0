#include "db/site_copy.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "db/site_database.hpp"
#include "db/site_schema.hpp"

namespace littermap::db {
namespace {

std::size_t CopyTable(const TableSpec& table, SiteDatabase& from, SiteDatabase& to,
                      const ProgressCallback& progress) {
  const std::string task = std::string("copying ") + table.name;
  std::string columns, select, values;
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    const ColumnSpec& column = table.columns[i];
    const std::string separator = i ? ", " : "";
    columns += separator + column.name;
    select += separator + (IsGeometry(column.type) ? from.GeometryColumn(column.name)
                                                   : std::string(column.name));
    const int parameter = static_cast<int>(i) + 1;
    values += separator + (IsGeometry(column.type) ? to.GeometryParameter(parameter)
                                                   : "?" + std::to_string(parameter));
  }
  const auto query = from.sql().Prepare("SELECT " + select + " FROM " + table.name + " ORDER BY " +
                                        table.columns.front().name);
  const auto insert = to.sql().Prepare("INSERT INTO " + std::string(table.name) + " (" + columns +
                                       ") VALUES (" + values + ")");
  std::size_t rows = 0;
  // A blob parameter is read when the row is inserted (SQLite binds it without a copy).
  std::vector<std::vector<std::uint8_t>> geometries(table.columns.size());
  while (query->Step()) {
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      const ColumnSpec& column = table.columns[i];
      const int c = static_cast<int>(i);
      const int parameter = c + 1;
      if (query->ColumnIsNull(c)) {
        insert->BindNull(parameter);
        continue;
      }
      switch (column.type) {
        case ColumnType::kId:
        case ColumnType::kInteger:
          insert->Bind(parameter, query->ColumnInt64(c));
          break;
        case ColumnType::kReal:
          insert->BindReal(parameter, query->ColumnDouble(c));
          break;
        case ColumnType::kText:
        case ColumnType::kNowUtc:
          insert->Bind(parameter, query->ColumnText(c));
          break;
        case ColumnType::kBlob:
          insert->BindBlob(parameter, query->ColumnBlob(c));
          break;
        case ColumnType::kPoint:
        case ColumnType::kLineString: {
          const GeometryBlob geometry = from.ReadGeometry(
              query->ColumnBlob(c), from.name() + ": " + table.name + " row " +
                                        std::to_string(rows + 1) + " " + column.name);
          geometries[i] = to.GeometryBytes(geometry.type, geometry.points);
          insert->BindBlob(parameter, geometries[i]);
          to.ExtendLayerExtent(table.name, EnvelopeOf(geometry.points));
          break;
        }
      }
    }
    insert->Run();
    if (++rows % 1000 == 0) ReportProgress(progress, {task, rows, 0});
  }
  ReportProgress(progress, {task, rows, rows});
  // Ids given explicitly do not move PostgreSQL's identity sequences (SQLite's AUTOINCREMENT
  // follows the largest id by itself): the next row after the copy must not reuse one.
  if (to.engine() == SqlEngine::kPostgres) {
    for (const ColumnSpec& column : table.columns) {
      if (column.type != ColumnType::kId) continue;
      to.sql().Execute("SELECT setval(pg_get_serial_sequence('" + std::string(table.name) + "', '" +
                       column.name + "'), (SELECT COALESCE(max(" + column.name + "), 0) + 1 FROM " +
                       table.name + "), false)");
    }
  }
  return rows;
}

}  // namespace

std::size_t SiteCopyResult::Rows(const std::string& table) const {
  const auto it =
      std::find_if(tables.begin(), tables.end(), [&](const Table& t) { return t.name == table; });
  return it == tables.end() ? 0 : it->rows;
}

SiteCopyResult CopySite(const SiteLocator& from, const SiteLocator& to,
                        const ProgressCallback& progress) {
  SiteDatabase source = SiteDatabase::OpenReadOnly(from);
  const SiteInfo& info = source.site();
  SiteOptions options;
  options.name = info.name;
  if (info.frame.georeferenced()) options.epsg_code = info.frame.epsg_code;
  options.origin_easting_m = info.frame.origin_easting_m;
  options.origin_northing_m = info.frame.origin_northing_m;
  options.rotation_deg = info.frame.rotation_deg;
  SiteDatabase target = SiteDatabase::Create(to, options);
  SiteCopyResult result;
  result.site_name = info.name;
  try {
    target.InTransaction([&] {
      result.tables.clear();
      // The site row and the schema version are the target's own; the site keeps its birthday.
      const auto created = target.sql().Prepare("UPDATE sites SET created_utc = ?");
      created->Bind(1, info.created_utc);
      created->Run();
      for (const TableSpec& table : SiteSchema()) {
        const std::string name = table.name;
        if (name == "sites" || name == "littermap_schema_version") continue;
        result.tables.push_back({name, CopyTable(table, source, target, progress)});
      }
    });
  } catch (...) {
    try {
      SiteDatabase::Remove(to);
    } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the copy's error counts
    }
    throw;
  }
  return result;
}

}  // namespace littermap::db
