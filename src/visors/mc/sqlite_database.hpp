#pragma once
// A thin RAII layer over the SQLite C API (Debian libsqlite3): a connection and prepared
// statements with typed binding and reading; every failure is an error with SQLite's message.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include "visors/core/result.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace visors::mc {

using SqlValue = std::variant<std::monostate, std::int64_t, double, std::string>;

class SqlStatement {
 public:
  SqlStatement(SqlStatement&& other) noexcept;
  SqlStatement& operator=(SqlStatement&& other) noexcept;
  SqlStatement(const SqlStatement&) = delete;
  SqlStatement& operator=(const SqlStatement&) = delete;
  ~SqlStatement();

  /// Binds parameter i (1-based).
  SqlStatement& bind(int i, const SqlValue& value);
  /// Runs to the next row: true while there is one, false when done; an error otherwise.
  core::Result<bool> step();
  [[nodiscard]] std::int64_t integer(int column) const;
  [[nodiscard]] double real(int column) const;  // NaN for NULL
  [[nodiscard]] std::string text(int column) const;
  [[nodiscard]] bool is_null(int column) const;

 private:
  friend class SqlDatabase;
  SqlStatement(sqlite3* db, sqlite3_stmt* statement) : db_(db), statement_(statement) {}
  sqlite3* db_ = nullptr;
  sqlite3_stmt* statement_ = nullptr;
};

class SqlDatabase {
 public:
  /// Opens (creating) the database file; busy waits up to 10 s for another writer.
  static core::Result<SqlDatabase> open(const std::filesystem::path& path);
  SqlDatabase(SqlDatabase&& other) noexcept;
  SqlDatabase& operator=(SqlDatabase&& other) noexcept;
  SqlDatabase(const SqlDatabase&) = delete;
  SqlDatabase& operator=(const SqlDatabase&) = delete;
  ~SqlDatabase();

  /// Runs one or more statements without results.
  core::Result<bool> execute(const std::string& sql);
  core::Result<SqlStatement> prepare(const std::string& sql);

 private:
  explicit SqlDatabase(sqlite3* db) : db_(db) {}
  sqlite3* db_ = nullptr;
};

}  // namespace visors::mc
