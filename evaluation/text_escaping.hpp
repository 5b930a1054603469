#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace radarpr {

// Every string that radarpr writes into another language passes through exactly one of these,
// chosen by the language of the file it lands in. The strings come from configs, results folders
// and plugins, which people share: a descriptor label or a dataset name must never become code in
// a gnuplot script, markup in a page, or a command in a spreadsheet. Each function returns text
// that the target language reads back as the same characters (control characters, which no
// target shows, become a space), so a label is shown, never executed. docs/security.md lists
// what each one does.

// A gnuplot single-quoted string literal, quotes included: '' for a quote; newlines and other
// control characters become a space, so the literal cannot end the command. Inside single quotes
// gnuplot expands neither backquotes (`command`) nor macros (@name), and backslashes are plain.
std::string gnuplot_string(std::string_view text);

// HTML text, and attribute values in double or single quotes: & < > " ' as entities; control
// characters other than tab and newline become a space.
std::string html_escape(std::string_view text);

// LaTeX text (T1 font encoding for \textquotedbl): the ten specials and < > " as commands;
// newlines and other control characters become a space (a blank line would end the table row).
std::string latex_escape(std::string_view text);

// A plain Markdown table cell: \ | ` * [ ] < as backslash escapes (GitHub splits the row at '|'
// first, so a trailing backslash would otherwise swallow the cell border); newlines and other
// control characters become a space.
std::string markdown_cell(std::string_view text);

// A Markdown table cell shown as code: a backtick fence longer than any backtick run inside,
// '|' escaped (the row is split before code spans are read), control characters as a space.
std::string markdown_code_cell(std::string_view text);

// A CSV field (RFC 4180): quoted when it holds a comma, quote, newline, carriage return or a
// leading or trailing space, with quotes doubled. Text a spreadsheet would read as a formula
// (starting with = + - @ or a tab, and not a number) is prefixed with ' so that it stays text.
// `always`: quoted whatever it holds (a column of free text).
enum class CsvQuoting { when_needed, always };
std::string csv_field(std::string_view text, CsvQuoting quoting = CsvQuoting::when_needed);

// Text for a message on the terminal or in a log: valid UTF-8 is kept, control characters and
// bytes that are not UTF-8 are shown as \n, \t, \xNN, so a name is shown readably and a name
// holding escape sequences cannot rewrite the terminal. `keep_newlines`: a message of several
// lines keeps them.
std::string printable(std::string_view text, bool keep_newlines = false);

// Whether `text` is valid UTF-8 (JSON strings must be).
bool is_utf8(std::string_view text);

// A string for a JSON file: `text` itself when it is valid UTF-8, else printable(text). File and
// folder names are bytes on Linux; a name that is not UTF-8 is stored readably (\xNN) instead of
// making the whole file unwritable (nlohmann's type_error.316 after all the work).
std::string json_string(std::string_view text);

// json_string applied to every string (and object key) in `value`.
void make_json_utf8(nlohmann::json& value);

}  // namespace radarpr
