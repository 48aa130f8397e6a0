#include "db/site_locator.hpp"

#include <cctype>
#include <vector>

#include "core/error.hpp"

namespace littermap::db {
namespace {

std::string PercentDecoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() &&
        std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i] == '+' ? ' ' : text[i];
    }
  }
  return out;
}

bool IsPlainIdentifier(const std::string& name) {
  if (name.empty() || name.size() > 63) return false;
  if (!(std::islower(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (char c : name) {
    if (!(std::islower(static_cast<unsigned char>(c)) ||
          std::isdigit(static_cast<unsigned char>(c)) || c == '_')) {
      return false;
    }
  }
  return true;
}

// The schema an options= value sets as the first of the search_path, if any.
std::string SearchPathSchema(const std::string& options) {
  const std::string key = "search_path=";
  const std::size_t at = options.find(key);
  if (at == std::string::npos) return {};
  std::string value = options.substr(at + key.size());
  value = value.substr(0, value.find_first_of(", "));
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
    value = value.substr(1, value.size() - 2);
  }
  return value;
}

}  // namespace

bool IsPostgresUri(const std::string& text) {
  return text.rfind("postgresql://", 0) == 0 || text.rfind("postgres://", 0) == 0;
}

SiteLocator ParseSiteLocator(const std::string& text, const std::string& what) {
  if (!IsPostgresUri(text)) return SiteLocator(std::filesystem::path(text));
  SiteLocator locator;
  const std::size_t question = text.find('?');
  const std::string base = text.substr(0, question);
  std::vector<std::string> kept;
  std::string site, options_schema;
  if (question != std::string::npos) {
    std::string query = text.substr(question + 1);
    std::size_t start = 0;
    while (start <= query.size()) {
      const std::size_t end = std::min(query.find('&', start), query.size());
      const std::string parameter = query.substr(start, end - start);
      const std::string key = parameter.substr(0, parameter.find('='));
      const std::string value =
          parameter.find('=') == std::string::npos ? "" : parameter.substr(key.size() + 1);
      if (key == "site") {
        site = PercentDecoded(value);
      } else if (!parameter.empty()) {
        if (key == "options") options_schema = SearchPathSchema(PercentDecoded(value));
        kept.push_back(parameter);
      }
      start = end + 1;
    }
  }
  locator.schema = site.empty() ? options_schema : site;
  if (locator.schema.empty()) {
    throw UsageError(what + ": " + base +
                     " names no site; add ?site=NAME (the schema that holds the site)");
  }
  if (!IsPlainIdentifier(locator.schema)) {
    throw UsageError(what + ": site name '" + locator.schema +
                     "' must be lower-case letters, digits and _ (a PostgreSQL schema name of at "
                     "most 63 bytes, starting with a letter or _)");
  }
  locator.conninfo = base;
  for (std::size_t i = 0; i < kept.size(); ++i) locator.conninfo += (i ? "&" : "?") + kept[i];
  // The display drops the parameters (one may be a password) and a password in the authority.
  std::string shown = base;
  const std::size_t scheme_end = shown.find("://") + 3;
  const std::size_t at = shown.find('@', scheme_end);
  const std::size_t colon = shown.find(':', scheme_end);
  if (at != std::string::npos && colon != std::string::npos && colon < at) {
    shown.erase(colon, at - colon);
  }
  locator.display = shown + " (site " + locator.schema + ")";
  return locator;
}

}  // namespace littermap::db
