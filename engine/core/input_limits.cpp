#include "core/input_limits.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/text_format.hpp"

namespace maris {

namespace {

std::string bytesText(std::uintmax_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// Builds the document from SAX events with an explicit stack of open containers (no recursion),
// tracking the JSON path of the value being read, so every refusal can name where it happened.
class LimitedDomBuilder {
 public:
  LimitedDomBuilder(std::string origin, std::string prefix) : origin_(std::move(origin)), prefix_(std::move(prefix)) {}

  bool null() { return put(Json(nullptr)); }
  bool boolean(bool v) { return put(Json(v)); }
  bool number_integer(Json::number_integer_t v) { return put(Json(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return put(Json(v)); }
  bool number_float(Json::number_float_t v, const std::string&) { return put(Json(v)); }
  bool binary(Json::binary_t&) { return fail(path(), "", "binary values are not accepted"); }
  bool string(std::string& v) {
    if (v.size() > InputLimits::kStringLength)
      return fail(path(), "", formatText("text of %zu characters; the limit is %zu", v.size(), InputLimits::kStringLength));
    return put(Json(std::move(v)));
  }
  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    Level& top = stack_.back();
    if (k.size() > InputLimits::kStringLength)
      return fail(path(), "", formatText("key of %zu characters; the limit is %zu", k.size(), InputLimits::kStringLength));
    if (top.node->contains(k)) {
      top.key = std::move(k);
      return fail(path(), "", "duplicate key (each key may appear once in an object)");
    }
    top.key = std::move(k);
    return true;
  }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) {
    if (e.id == 406)  // out_of_range: a number beyond the range of a double
      return fail(path(), echoText(token), "number is out of the range of a double (about ±1.8e308)");
    syntax_message_ = e.what();
    return false;
  }

  Json& document() { return root_; }
  const std::optional<FieldError>& error() const { return error_; }
  const std::string& syntaxMessage() const { return syntax_message_; }

 private:
  struct Level {
    Json* node;
    std::string key;      // objects: the key whose value comes next
    std::size_t count = 0;  // arrays: elements so far
  };

  std::string path() const {
    std::string p = prefix_;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Level& level = stack_[i];
      if (level.node->is_object()) {
        if (!p.empty()) p += '.';
        p += level.key;
      } else {  // an open container below is the array's last element; at the top, the next one is read
        const std::size_t index = i + 1 < stack_.size() ? level.count - 1 : level.count;
        p += "[" + std::to_string(index) + "]";
      }
    }
    return p.empty() ? "(document)" : p;
  }

  bool fail(const std::string& where, const std::string& value, const std::string& message) {
    error_ = FieldError{where, value, message + " (in " + echoText(origin_) + ")"};
    return false;
  }

  // Places a value at the current position; returns the stored value.
  Json* place(Json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Level& top = stack_.back();
    if (top.node->is_object()) return &((*top.node)[top.key] = std::move(v));
    top.node->push_back(std::move(v));
    ++top.count;
    return &top.node->back();
  }

  bool roomInArray() {
    if (stack_.empty() || !stack_.back().node->is_array() || stack_.back().count < InputLimits::kArrayLength) return true;
    return fail(path(), "", formatText("array longer than %zu elements", InputLimits::kArrayLength));
  }

  bool put(Json&& v) {
    if (!roomInArray()) return false;
    place(std::move(v));
    return true;
  }

  bool open(Json&& container) {
    if (stack_.size() >= InputLimits::kJsonDepth)
      return fail(path(), "", formatText("nested deeper than %zu levels of arrays and objects", InputLimits::kJsonDepth));
    if (!roomInArray()) return false;
    stack_.push_back(Level{place(std::move(container)), {}, 0});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  std::string origin_, prefix_;
  Json root_;
  std::vector<Level> stack_;
  std::optional<FieldError> error_;
  std::string syntax_message_;
};

}  // namespace

std::string readInputFile(const std::filesystem::path& file, const std::string& what, std::uintmax_t max_bytes) {
  const std::string name = echoText(file.string());
  const std::string value = what == file.string() ? std::string() : "\"" + name + "\"";
  auto refuse = [&](const std::string& message) { throw InputError(echoText(what), value, message); };
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ELOOP) refuse("is a loop of symbolic links; cannot be read");
    if (err == ENOENT) refuse("does not exist");
    refuse(std::string("cannot be read: ") + std::strerror(err));
  }
  if (S_ISDIR(st.st_mode)) refuse("is a folder, not a file");
  if (!S_ISREG(st.st_mode)) refuse("is not a regular file (a device, pipe or socket); only regular files are read");
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    refuse(formatText("is %jd bytes; the limit is ", static_cast<intmax_t>(st.st_size)) + bytesText(max_bytes));
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) refuse(std::string("cannot be opened: ") + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      refuse(std::string("cannot be read: ") + std::strerror(err));
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {  // grew while being read
      ::close(fd);
      refuse("is larger than the limit of " + bytesText(max_bytes));
    }
  }
  ::close(fd);
  return text;
}

Json parseJsonLimited(const std::string& text, const std::string& origin, const std::string& path_prefix) {
  LimitedDomBuilder builder(origin, path_prefix);
  const bool ok = Json::sax_parse(text, &builder);
  if (builder.error()) throw InputError(std::vector<FieldError>{*builder.error()});
  if (!ok) {
    // Turn the parser's byte offset into line and column for the message.
    std::size_t line = 1, col = 1;
    const auto at = builder.syntaxMessage().find("at line ");
    if (at != std::string::npos) {
      std::sscanf(builder.syntaxMessage().c_str() + at, "at line %zu, column %zu", &line, &col);
    }
    throw JsonSyntaxError(echoText(origin), "",
                          "is not valid JSON (line " + std::to_string(line) + ", column " + std::to_string(col) + ")");
  }
  return std::move(builder.document());
}

void checkDataShape(const std::string& text, const std::string& field, const std::string& file) {
  // A row's columns: its comma/semicolon-separated fields or its blank-separated tokens, whichever is more.
  std::size_t rows = 0, separators = 0, tokens = 0;
  bool in_token = false;
  const std::string value = "\"" + echoText(file) + "\"";
  auto endRow = [&] {
    ++rows;
    if (rows > InputLimits::kDataRows)
      throw InputError(field, value, formatText("has more than %zu rows (the limit)", InputLimits::kDataRows));
    const std::size_t columns = std::max(separators + 1, tokens);
    if (columns > InputLimits::kDataColumns)
      throw InputError(field, value,
                       formatText("row %zu has %zu columns; the limit is %zu", rows, columns, InputLimits::kDataColumns));
    separators = tokens = 0;
    in_token = false;
  };
  for (const char c : text) {
    if (c == '\n') {
      endRow();
    } else if (c == ',' || c == ';') {
      ++separators;
      in_token = false;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      in_token = false;
    } else if (!in_token) {
      in_token = true;
      ++tokens;
    }
  }
  if (!text.empty() && text.back() != '\n') endRow();
}

}  // namespace maris
