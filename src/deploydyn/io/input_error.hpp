#pragma once
// Error in user input: names where (file, line, column), which field (dotted path), and what
// is allowed. what() is the full one-line message, e.g.
//   model.yaml:17:5: elements.2.area: must be positive (m²), got -1
// with control characters and bytes that are not UTF-8 escaped (io::printable): a message may
// quote a binary file or an ANSI escape sequence, and must not play it on the terminal. Quoted
// input is cut to an excerpt (io::excerpt) where the message is made; the field here.

#include <stdexcept>
#include <string>

#include "deploydyn/io/text_file.hpp"

namespace deploydyn {

class InputError : public std::runtime_error {
 public:
  InputError(std::string source, int line, int column, std::string field, std::string problem)
      : std::runtime_error(format(source, line, column, field, problem)),
        source_(std::move(source)),
        line_(line),
        column_(column),
        field_(std::move(field)),
        problem_(std::move(problem)) {}

  const std::string& source() const { return source_; }  // file name or "--set PATH=VALUE"
  int line() const { return line_; }                      // 1-based; 0 when unknown
  int column() const { return column_; }                  // 1-based; 0 when unknown
  const std::string& field() const { return field_; }     // dotted path, e.g. "elements.2.area"
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& source, int line, int column,
                            const std::string& field, const std::string& problem) {
    std::string text = source;
    if (line > 0) text.append(":").append(std::to_string(line));
    if (line > 0 && column > 0) text.append(":").append(std::to_string(column));
    text.append(": ");
    // A field is a few keys; a longer one holds a pasted text as a key.
    if (!field.empty()) text.append(io::excerpt(field, 4 * io::kMaxExcerptChars)).append(": ");
    return io::printable(text.append(problem));
  }

  std::string source_;
  int line_;
  int column_;
  std::string field_;
  std::string problem_;
};

}  // namespace deploydyn
