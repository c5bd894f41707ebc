#include <bimrock/io/msh_lines.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <bimrock/model/errors.hpp>

namespace bimrock::msh {

Words::Words(std::string_view line, const std::string& file, int number)
    : file_(file), number_(number) {
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t'))
      ++k;
    const std::size_t start = k;
    while (k < line.size() && line[k] != ' ' && line[k] != '\t')
      ++k;
    if (k > start)
      words_.push_back(line.substr(start, k - start));
  }
}

void Words::fail(const std::string& item, const std::string& message) const {
  throw InputError(file_, number_, item, message);
}

void Words::expect_count(std::size_t n, const std::string& item, const char* what,
                         bool at_least) const {
  if (words_.size() < n || (!at_least && words_.size() > n)) {
    fail(item, std::string("expected ") + what + " (" + (at_least ? "at least " : "") +
                   std::to_string(n) + " values), found " + std::to_string(words_.size()));
  }
}

std::int64_t Words::integer(std::size_t k, const std::string& item, const char* what) const {
  const std::string_view w = at(k, item, what);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
  if (ec != std::errc() || end != w.data() + w.size())
    fail(item,
         std::string("expected ") + what + " (a whole number), found '" + std::string(w) + "'");
  return value;
}

int Words::count(std::size_t k, const std::string& item, const char* what) const {
  const std::int64_t value = integer(k, item, what);
  if (value < 0 || value > std::numeric_limits<int>::max())
    fail(item, std::string(what) + " out of range: " + std::to_string(value));
  return static_cast<int>(value);
}

double Words::real(std::size_t k, const std::string& item, const char* what) const {
  std::string_view w = at(k, item, what);
  if (!w.empty() && w.front() == '+')
    w.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
  if (ec != std::errc() || end != w.data() + w.size())
    fail(item, std::string("expected ") + what + " (a number), found '" + std::string(w) + "'");
  if (!std::isfinite(value))
    fail(item, std::string(what) + " is not a finite number");
  return value;
}

std::string_view Words::at(std::size_t k, const std::string& item, const char* what) const {
  if (k >= words_.size())
    fail(item, std::string("expected ") + what + ": the line ends early");
  return words_[k];
}

std::optional<std::string_view> Cursor::next_or_end() {
  while (pos_ < text_.size()) {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view l = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t'))
      l.remove_suffix(1);
    while (!l.empty() && (l.front() == ' ' || l.front() == '\t'))
      l.remove_prefix(1);
    if (!l.empty())
      return l;
  }
  return std::nullopt;
}

std::string_view Cursor::next(const std::string& section) {
  const std::optional<std::string_view> l = next_or_end();
  if (!l)
    fail(section, "the file ends inside the section (is it cut short?)");
  if (l->front() == '$')
    fail(section, "the section ends early, at '" + std::string(*l) + "'");
  return *l;
}

Words Cursor::words(const std::string& section) {
  const std::string_view l = next(section);  // first: it advances line_
  return Words(l, file_, line_);
}

void Cursor::expect_end(const std::string& section) {
  const std::string end = "$End" + section.substr(1);
  const std::optional<std::string_view> l = next_or_end();
  if (!l || *l != end) {
    fail(section, "expected '" + end + "' here, found " +
                      (l ? std::string("'").append(l->substr(0, 40)).append("'")
                         : std::string("the end of the file")) +
                      " (more entries than the section's header announces?)");
  }
}

void Cursor::skip(const std::string& section) {
  const std::string end = "$End" + section.substr(1);
  const int start = line_;
  while (const std::optional<std::string_view> l = next_or_end()) {
    if (*l == end)
      return;
  }
  throw InputError(file_, start, section, "the section is not closed by '" + end + "'");
}

void Cursor::fail(const std::string& item, const std::string& message) const {
  throw InputError(file_, line_, item, message);
}

}  // namespace bimrock::msh
