// The structure checks of OFF, PLY and OBJ files (see mesh_input.h).
#include "detail.h"

#include <CGAL/IO/OFF/File_header_extended_OFF.h>
#include <CGAL/IO/io.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ios>
#include <sstream>

namespace mesh_input {
namespace detail {

// ------------------------------------------------------------ OFF structure

// Element counts larger than this cannot be genuine: every element takes at
// least one byte of the file. (CGAL's readers reserve memory for the counts
// of a header before reading any element.)
inline void check_count(const std::string& filename, const std::string& what, long long count,
                        std::uintmax_t file_size)
{
  if(count < 0)
    cannot_read(filename, "its header announces a negative number of " + what + " (" +
                          std::to_string(count) + ")");
  if(std::uintmax_t(count) > file_size || count > (1LL << 30))
    cannot_read(filename, "its header announces " + std::to_string(count) + " " + what +
                          " in a file of " + std::to_string(file_size) + " bytes");
}

// True if `token` is, as a whole, a number that is not finite ("nan",
// "inf", "1e999", ...): such a vertex is reported as non-finite rather than
// as unreadable (CGAL's readers reject some of these spellings).
inline bool is_non_finite_token(const std::string& token)
{
  if(token.empty()) return false;
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(x);
}

[[noreturn]] inline void non_finite_vertex(const std::string& filename, long long v, const std::string& token)
{
  fail("ERROR_NON_FINITE_COORDINATE", quoted(filename) + ": vertex " + std::to_string(v) +
                                      " has a non-finite coordinate '" + token.substr(0, 30) + "'");
}

// A token of an OFF face line must be a non-negative integer (CGAL reads it
// as a double and casts it to an unsigned integer).
inline bool is_index_value(double x, double bound)
{
  return std::isfinite(x) && x >= 0. && x < bound && x == std::floor(x);
}

// Colors as CGAL's OFF scanner converts them (File_scanner_OFF::scan_color):
// integers are cast to unsigned char, other values are scaled by 255 first.
// Only values that survive the cast are accepted.
inline bool is_valid_off_color(const double* rgb)
{
  bool integers = true;
  for(int k = 0; k < 3; ++k)
  {
    if(!std::isfinite(rgb[k])) return false;
    integers = integers && std::floor(rgb[k]) == rgb[k];
  }
  for(int k = 0; k < 3; ++k)
  {
    const double x = integers ? rgb[k] : rgb[k] * 255.;
    if(!(x >= 0. && x < 256.)) return false;
  }
  return true;
}

// Walks an OFF file the way CGAL's File_scanner_OFF does (same header
// grammar, one line per vertex and per face in ASCII) and refuses what that
// reader does not handle safely: texture coordinates (STOFF) and n-dimensional
// files (nOFF), colors in binary files, short lines or out-of-range values in
// colored files, invalid face sizes and vertex indices, and counts the file
// cannot hold.
inline void check_off_stream(std::istream& in, const std::string& filename, std::uintmax_t file_size)
{
  char c = 0;
  while((in >> c) && c == '#') in >> CGAL::skip_until_EOL;
  if(!in) cannot_read(filename, "no OFF header");
  std::string keyword(1, c);
  while(keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) keyword += c;
  // [ST][C][N][4][n]OFF
  std::size_t j = 0;
  bool textures = false, colors = false, normals = false, homogeneous = false, dimensional = false;
  if(keyword.compare(j, 2, "ST") == 0) { textures = true; j += 2; }
  if(j < keyword.size() && keyword[j] == 'C') { colors = true; ++j; }
  if(j < keyword.size() && keyword[j] == 'N') { normals = true; ++j; }
  if(j < keyword.size() && keyword[j] == '4') { homogeneous = true; ++j; }
  if(j < keyword.size() && keyword[j] == 'n') { dimensional = true; ++j; }
  if(keyword.substr(j) != "OFF")
    cannot_read(filename, "not an OFF file (header '" + keyword.substr(0, 20) + "')");
  if(textures) cannot_read(filename, "OFF files with texture coordinates (" + keyword + ") are not supported");
  if(dimensional) cannot_read(filename, "n-dimensional OFF files (" + keyword + ") are not supported");

  in >> CGAL::skip_comment_OFF;
  c = 0;
  if(!(in >> c)) cannot_read(filename, "its OFF header has no element counts");
  long long vertices = 0, faces = 0, edges = 0;
  const bool binary = !std::isdigit(static_cast<unsigned char>(c));
  if(binary)
  {
    std::string word(1, c);
    while(word.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) word += c;
    if(word != "BINARY") cannot_read(filename, "its OFF header has no valid element counts");
    if(colors) cannot_read(filename, "binary OFF files with colors are not supported");
    if(c != '\n') in >> CGAL::skip_until_EOL;
    auto read_int32 = [&]() -> long long {
      unsigned char b[4];
      if(!in.read(reinterpret_cast<char*>(b), 4)) cannot_read(filename, "truncated binary OFF header");
      const std::uint32_t u = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                              (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]);
      return (long long)std::int32_t(u);
    };
    vertices = read_int32();
    faces = read_int32();
    edges = read_int32();
  }
  else
  {
    in.putback(c);
    if(!(in >> vertices >> faces >> edges)) cannot_read(filename, "its OFF header has no valid element counts");
  }
  check_count(filename, "vertices", vertices, file_size);
  check_count(filename, "faces", faces, file_size);
  check_count(filename, "edges", edges, file_size);
  if(binary) return; // face sizes are bounded by Checked_polygon, indices checked by CGAL

  std::string line, token;
  std::vector<double> entries;
  // (a truncated file is refused here: CGAL's scanner would go on reading
  // colors of lines it could not read)
  auto read_entries = [&](const std::string& what, long long i, long long count) {
    in >> CGAL::skip_comment_OFF;
    if(!std::getline(in, line))
      cannot_read(filename, "the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                            " " + what);
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    entries.clear();
    double d = 0.;
    while(words >> CGAL::IO::iformat(d)) entries.push_back(d);
  };
  // CGAL's scanner remembers that an element had colors and then reads
  // colors for every later one: they must all have them.
  bool colors_seen = false;
  auto check_colors = [&](std::size_t first, const std::string& where) {
    const std::size_t n = entries.size() - first;
    if(n == 0 && !colors_seen) return;
    if(n != 3 && n != 4)
      cannot_read(filename, where + " has " + std::to_string(n) + " color values (expected 3 or 4" +
                            (colors_seen ? ", as earlier elements have colors)" : " or none)"));
    if(!is_valid_off_color(&entries[first])) cannot_read(filename, where + " has an invalid color");
    colors_seen = true;
  };

  const std::size_t h = homogeneous ? 1 : 0;
  const std::size_t vertex_values = (3 + h) * (normals ? 2 : 1);
  for(long long i = 0; i < vertices; ++i)
  {
    read_entries("vertices", i, vertices);
    std::istringstream words(line);
    for(int k = 0; k < 3 && words >> token; ++k)
      if(is_non_finite_token(token)) non_finite_vertex(filename, i, token);
    if(!colors) continue;
    const std::string where = "vertex " + std::to_string(i);
    if(entries.size() < vertex_values)
      cannot_read(filename, where + " has " + std::to_string(entries.size()) + " values, expected at least " +
                            std::to_string(vertex_values));
    check_colors(vertex_values, where);
  }
  colors_seen = false;
  for(long long f = 0; f < faces; ++f)
  {
    read_entries("faces", f, faces);
    const std::string where = "face " + std::to_string(f);
    if(entries.empty()) cannot_read(filename, where + " has no vertex count");
    if(!is_index_value(entries[0], double(entries.size())))
      cannot_read(filename, where + " (line '" + line.substr(0, 40) + "') has an invalid vertex count");
    const std::size_t n = std::size_t(entries[0]);
    for(std::size_t k = 1; k <= n; ++k)
      if(!is_index_value(entries[k], double(vertices)))
      {
        std::ostringstream value;
        value << entries[k];
        cannot_read(filename, where + " refers to vertex " + value.str() + ", but the file has " +
                              std::to_string(vertices) + " vertices");
      }
    if(colors) check_colors(n + 1, where);
  }
}

// The whole file as bytes.
inline std::string file_bytes(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// An OFF file whose first count follows its keyword without a space
// ("OFF8 6 12", as some exporters write): CGAL's header scanner takes
// "OFF8" for one keyword and refuses it, so CGAL reads the file with a space
// put there. The keyword is read as that scanner reads it.
void check_off_structure(const std::string& filename, std::uintmax_t file_size, std::string& normalized,
                         std::vector<std::string>& notes)
{
  normalized.clear();
  std::ifstream in(filename, std::ios::binary);
  char c = 0;
  while((in >> c) && c == '#') in >> CGAL::skip_until_EOL;
  const std::streamoff start = in ? std::streamoff(in.tellg()) - 1 : -1;
  std::string keyword(1, c);
  while(in && keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) keyword += c;
  const std::size_t off = keyword.find("OFF");
  std::size_t digits = 0;
  if(start >= 0 && off != std::string::npos && off + 3 < keyword.size() &&
     keyword.find_first_not_of("STCN4n") >= off) // [ST][C][N][4][n]OFF, then the count
  {
    digits = keyword.size() - off - 3;
    for(std::size_t k = off + 3; k < keyword.size(); ++k)
      if(!std::isdigit(static_cast<unsigned char>(keyword[k]))) digits = 0;
  }
  if(digits == 0)
  {
    in.clear();
    in.seekg(0);
    check_off_stream(in, filename, file_size);
    return;
  }
  normalized = file_bytes(filename);
  normalized.insert(std::size_t(start) + off + 3, 1, ' ');
  std::istringstream fixed(normalized);
  check_off_stream(fixed, filename, file_size + 1);
  notes.push_back("OFF header '" + keyword + "': its first element count follows the keyword without a space, read as '" +
                  keyword.substr(0, off + 3) + " " + keyword.substr(off + 3) + "'");
}

// ------------------------------------------------------------ PLY structure

struct Ply_property
{
  std::string name;
  bool list = false;
  int count_size = 0; // bytes of the list count type
  int size = 0;       // bytes of the scalar / list item type
  bool count_signed = false, is_float = false;
};

struct Ply_element
{
  std::string name;
  long long count = 0;
  std::vector<Ply_property> properties;
};

// Byte size of a PLY scalar type, 0 if unknown.
inline int ply_type_size(const std::string& type, bool& is_signed, bool& is_float)
{
  is_signed = false;
  is_float = false;
  if(type == "char" || type == "int8") { is_signed = true; return 1; }
  if(type == "uchar" || type == "uint8") return 1;
  if(type == "short" || type == "int16") { is_signed = true; return 2; }
  if(type == "ushort" || type == "uint16") return 2;
  if(type == "int" || type == "int32") { is_signed = true; return 4; }
  if(type == "uint" || type == "uint32") return 4;
  if(type == "float" || type == "float32") { is_signed = true; is_float = true; return 4; }
  if(type == "double" || type == "float64") { is_signed = true; is_float = true; return 8; }
  return 0;
}

// A token CGAL's ASCII PLY reader consumes whole: an integer for integer
// types; for floating types, only characters its number parser takes (it
// would split other tokens and shift every later value).
inline bool is_ply_ascii_token(const std::string& token, bool is_float)
{
  if(token.empty()) return false;
  if(is_float)
  {
    for(char ch : token)
      if(!std::isdigit(static_cast<unsigned char>(ch)) && ch != '.' && ch != 'e' && ch != 'E' &&
         ch != '+' && ch != '-')
        return false;
    double x = 0.;
    return std::sscanf(token.c_str(), "%lf", &x) == 1;
  }
  std::size_t k = (token[0] == '-' || token[0] == '+') ? 1 : 0;
  if(k == token.size() || token.size() - k > 18) return false;
  for(; k < token.size(); ++k)
    if(!std::isdigit(static_cast<unsigned char>(token[k]))) return false;
  return true;
}

// Name of a "property list <count type> <item type> <name>" line.
inline std::string item_name_of(const std::string& line)
{
  std::istringstream words(line);
  std::string word, name;
  for(int k = 0; k < 5 && words >> word; ++k) name = word;
  return name;
}

// ASCII PLY data written one element per line, where some lines carry
// values after those the header lists (VCG/MeshLab writes faces so): CGAL
// reads values one after the other, whatever the lines, and would take
// these for the next element's. If every element of the header is on a
// line of its own with at least its values, and nothing but blank lines
// follows the last, `normalized` gets the header and the lines without
// their extra values (`data_start`: where the data starts in it), `notes`
// a line per element kind, and the result is true. Otherwise (elements over
// several lines, or several on one line: CGAL reads those as they are) `in`
// is left where it was and the result is false.
inline bool cut_extra_ply_values(std::istream& in, const std::vector<Ply_element>& elements, std::string& normalized,
                                 std::size_t& data_start, std::vector<std::string>& notes)
{
  const std::streamoff start = in.tellg();
  if(start < 0) return false;
  struct Cut { long long lines = 0, first = 0; std::size_t values = 0; };
  std::vector<Cut> cuts(elements.size());
  std::string line, token;
  std::vector<std::string> tokens;
  // One walk over the lines; `data` (if not null) gets them without their
  // extra values. False if the data is not one element per line.
  auto walk = [&](std::string* data) {
    in.clear();
    in.seekg(start);
    for(std::size_t e = 0; e < elements.size(); ++e)
      for(long long item = 0; item < elements[e].count; ++item)
      {
        do
          if(!std::getline(in, line)) return false;
        while(line.find_first_not_of(" \t\r") == std::string::npos);
        std::istringstream words(line);
        tokens.clear();
        while(words >> token) tokens.push_back(token);
        std::size_t used = 0;
        for(const Ply_property& p : elements[e].properties)
        {
          if(used >= tokens.size()) return false;
          if(!p.list)
          {
            ++used;
            continue;
          }
          if(!is_ply_ascii_token(tokens[used], false)) return false;
          const long long n = std::stoll(tokens[used++]);
          if(n < 0 || std::uintmax_t(n) > tokens.size() - used) return false;
          used += std::size_t(n);
        }
        if(used < tokens.size() && !data)
        {
          if(cuts[e].lines++ == 0) cuts[e].first = item;
          cuts[e].values = (std::max)(cuts[e].values, tokens.size() - used);
        }
        if(data)
        {
          for(std::size_t k = 0; k < used; ++k) *data += (k ? " " : "") + tokens[k];
          *data += '\n';
        }
      }
    while(std::getline(in, line))
      if(line.find_first_not_of(" \t\r") != std::string::npos) return false;
    return true;
  };
  bool cut = false;
  if(walk(nullptr))
    for(const Cut& c : cuts) cut = cut || c.lines > 0;
  std::string data;
  if(cut)
  {
    in.clear();
    in.seekg(0);
    normalized.assign(std::size_t(start), '\0');
    cut = bool(in.read(&normalized[0], start)) && walk(&data);
  }
  if(!cut)
  {
    normalized.clear();
    in.clear();
    in.seekg(start);
    return false;
  }
  data_start = normalized.size();
  normalized += data;
  for(std::size_t e = 0; e < elements.size(); ++e)
    if(cuts[e].lines > 0)
      notes.push_back(std::to_string(cuts[e].lines) + " '" + elements[e].name.substr(0, 30) +
                      "' element lines of the PLY file (first: element " + std::to_string(cuts[e].first) +
                      ") end with values that its header does not list (up to " + std::to_string(cuts[e].values) +
                      " more): ignored");
  return true;
}

// Parses the header the way CGAL's PLY_reader does, then walks every
// element: list sizes must be non-negative integers that fit in the data
// left, and the data must not end early.
void check_ply_structure(const std::string& filename, std::uintmax_t file_size, std::string& normalized,
                         std::vector<std::string>& notes)
{
  normalized.clear();
  std::ifstream in(filename, std::ios::binary);
  std::string line;
  int format = -1; // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  bool header_done = false;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::string keyword;
    if(number == 1)
    {
      if(!(words >> keyword) || keyword != "ply") cannot_read(filename, "not a PLY file");
      continue;
    }
    if(number == 2)
    {
      std::string tag, name;
      words >> tag >> name;
      if(name == "ascii") format = 0;
      else if(name == "binary_little_endian") format = 1;
      else if(name == "binary_big_endian") format = 2;
      else cannot_read(filename, "unknown PLY format '" + name.substr(0, 30) + "'");
      continue;
    }
    if(!(words >> keyword)) cannot_read(filename, "empty line " + std::to_string(number) + " in the PLY header");
    if(keyword == "end_header") { header_done = true; break; }
    if(keyword == "element")
    {
      Ply_element e;
      std::string count;
      if(!(words >> e.name >> count) || !is_ply_ascii_token(count, false) || count[0] == '+')
        cannot_read(filename, "invalid element line " + std::to_string(number) + " in the PLY header");
      e.count = std::stoll(count);
      check_count(filename, "'" + e.name.substr(0, 30) + "' elements", e.count, file_size);
      elements.push_back(e);
    }
    else if(keyword == "property")
    {
      if(elements.empty())
        cannot_read(filename, "PLY property before any element (line " + std::to_string(number) + ")");
      std::string type, name;
      if(!(words >> type >> name))
        cannot_read(filename, "invalid property line " + std::to_string(number) + " in the PLY header");
      Ply_property p;
      bool is_signed = false, is_float = false;
      if(type == "list")
      {
        std::string item_type;
        if(!(words >> item_type))
          cannot_read(filename, "invalid property line " + std::to_string(number) + " in the PLY header");
        p.list = true;
        p.count_size = ply_type_size(name, p.count_signed, is_float);
        if(p.count_size == 0 || is_float)
          cannot_read(filename, "PLY list '" + item_type.substr(0, 30) + "' has an unsupported size type '" +
                                name.substr(0, 30) + "' (expected an integer type)");
        type = item_type;
      }
      p.size = ply_type_size(type, is_signed, p.is_float);
      if(p.size == 0)
        cannot_read(filename, "unknown PLY property type '" + type.substr(0, 30) + "' (line " +
                              std::to_string(number) + ")");
      p.name = p.list ? item_name_of(line) : name;
      // CGAL reads these with a fixed type and asserts (or, without
      // assertions, dereferences a null pointer) on any other one.
      const std::string& element = elements.back().name;
      const std::string where = "PLY property '" + p.name.substr(0, 30) + "' of '" + element.substr(0, 30) + "'";
      if((element == "vertex" || element == "vertices") && (p.name == "x" || p.name == "y" || p.name == "z") &&
         (p.list || !p.is_float))
        cannot_read(filename, where + " must be a float or a double");
      if(element == "halfedge" && (p.name == "source" || p.name == "target") &&
         (p.list || p.is_float || is_signed || p.size != 4))
        cannot_read(filename, where + " must be a uint");
      elements.back().properties.push_back(p);
    }
    // comment, obj_info, ...: ignored, as CGAL does
  }
  if(!header_done) cannot_read(filename, "the PLY header has no end_header line");
  if(format < 0) cannot_read(filename, "the PLY header has no format line");

  auto truncated = [&](const Ply_element& e, long long item) {
    cannot_read(filename, "PLY data ends inside '" + e.name.substr(0, 30) + "' element " + std::to_string(item));
  };
  auto bad_list = [&](const Ply_element& e, long long item, const std::string& size) {
    cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                          " has a list of invalid size " + size.substr(0, 30));
  };

  if(format == 0)
  {
    // values the header does not list at the end of element lines: cut off
    std::istringstream fixed;
    std::size_t data_start = 0;
    const bool cut = cut_extra_ply_values(in, elements, normalized, data_start, notes);
    if(cut)
    {
      fixed.str(normalized);
      fixed.seekg(std::streamoff(data_start));
    }
    std::istream& data = cut ? static_cast<std::istream&>(fixed) : in;
    std::string token;
    for(const Ply_element& e : elements)
      for(long long item = 0; item < e.count; ++item)
        for(const Ply_property& p : e.properties)
        {
          if(!(data >> token)) truncated(e, item);
          if(!p.list)
          {
            if(p.is_float && is_non_finite_token(token) && (e.name == "vertex" || e.name == "vertices"))
              non_finite_vertex(filename, item, token);
            if(!is_ply_ascii_token(token, p.is_float))
              cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                                    " has an invalid value '" + token.substr(0, 30) + "'");
            continue;
          }
          if(!is_ply_ascii_token(token, false)) bad_list(e, item, token);
          const long long n = std::stoll(token);
          const long long max = (1LL << (8 * p.count_size - (p.count_signed ? 1 : 0))) - 1;
          if(n < 0 || n > max || std::uintmax_t(n) > file_size) bad_list(e, item, token);
          for(long long k = 0; k < n; ++k)
          {
            if(!(data >> token)) truncated(e, item);
            if(!is_ply_ascii_token(token, p.is_float))
              cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                                    " has an invalid list value '" + token.substr(0, 30) + "'");
          }
        }
    return;
  }

  const std::streamoff data_start = in.tellg();
  if(data_start < 0) cannot_read(filename, "unreadable PLY data");
  std::uintmax_t position = std::uintmax_t(data_start);
  std::vector<unsigned char> bytes(8);
  for(const Ply_element& e : elements)
    for(long long item = 0; item < e.count; ++item)
      for(const Ply_property& p : e.properties)
      {
        if(!p.list)
        {
          if(position + std::uintmax_t(p.size) > file_size) truncated(e, item);
          position += std::uintmax_t(p.size);
          continue;
        }
        if(position + std::uintmax_t(p.count_size) > file_size) truncated(e, item);
        in.seekg(std::streamoff(position));
        if(!in.read(reinterpret_cast<char*>(bytes.data()), p.count_size)) truncated(e, item);
        position += std::uintmax_t(p.count_size);
        std::uint64_t u = 0;
        for(int k = 0; k < p.count_size; ++k)
        {
          const int b = format == 1 ? p.count_size - 1 - k : k; // most significant first
          u = (u << 8) | bytes[std::size_t(b)];
        }
        long long n = (long long)u;
        if(p.count_signed && (u >> (8 * p.count_size - 1)) != 0) n = -1;
        if(n < 0) bad_list(e, item, "-");
        const std::uintmax_t need = std::uintmax_t(n) * std::uintmax_t(p.size);
        if(need > file_size - position) bad_list(e, item, std::to_string(n));
        position += need;
      }
}

// ------------------------------------------------------------ OBJ structure

// Line keywords CGAL's OBJ reader accepts (it refuses the whole file on any
// other one).
inline bool is_known_obj_keyword(const std::string& s)
{
  static const char* const known[] = {"v", "vt", "vn", "f", "vp", "bevel", "lod", "ctech", "c_interp",
    "usemap", "usemtl", "stech", "d_interp", "mtllib", "shadow_obj", "trace_obj", "o", "g", "s", "p",
    "cstype", "deg", "step", "bmat", "con", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc",
    "cdp", "res"};
  if(!s.empty() && s[0] == '#') return true;
  for(const char* k : known)
    if(s == k) return true;
  return false;
}

// The statements of an OBJ file: its lines, where a line ending with a
// backslash goes on with the next (the OBJ format's line continuation, which
// CGAL's reader does not know; a comment does not go on). `continued`
// counts the lines joined so.
class Obj_statements
{
public:
  explicit Obj_statements(const std::string& filename) : in_(filename, std::ios::binary) {}
  // The next statement and the number of its first line; false at the end.
  bool next(std::string& statement, long long& number)
  {
    statement.clear();
    number = number_ + 1;
    std::string line;
    while(std::getline(in_, line))
    {
      ++number_;
      const std::size_t last = line.find_last_not_of(" \t\r");
      const std::size_t first = line.find_first_not_of(" \t\r");
      const bool comment = statement.empty() && first != std::string::npos && line[first] == '#';
      if(comment || last == std::string::npos || line[last] != '\\')
      {
        statement += line;
        return true;
      }
      statement += line.substr(0, last);
      statement += ' ';
      ++continued;
    }
    return !statement.empty();
  }
  long long continued = 0;

private:
  std::ifstream in_;
  long long number_ = 0;
};

// Names what CGAL's OBJ reader would refuse, before it does: a
// non-finite coordinate, an unknown statement, no face at all. Where the
// file has line continuations or polylines (`l`, which CGAL's reader
// refuses; like points, `p`, which it skips, they have no place in a
// surface), `normalized` gets its statements, one a line, without the
// polylines.
void check_obj_structure(const std::string& filename, std::string& normalized, std::vector<std::string>& notes)
{
  normalized.clear();
  Obj_statements statements(filename);
  std::string line, keyword, token;
  long long vertex = 0, faces = 0, polylines = 0, points = 0, number = 0;
  while(statements.next(line, number))
  {
    std::istringstream words(line);
    if(!(words >> keyword)) continue;
    if(keyword == "v")
    {
      for(int k = 0; k < 3 && words >> token; ++k)
        if(is_non_finite_token(token)) non_finite_vertex(filename, vertex, token);
      ++vertex;
    }
    else if(keyword == "f") ++faces;
    else if(keyword == "l") ++polylines;
    else if(keyword == "p") ++points;
    else if(!is_known_obj_keyword(keyword))
      cannot_read(filename, "line " + std::to_string(number) + ": unsupported OBJ statement '" +
                            keyword.substr(0, 30) + "'");
  }
  const std::string ignored = std::to_string(polylines) + " polyline ('l') and " + std::to_string(points) +
                              " point ('p') statements ignored";
  if(faces == 0)
    fail("ERROR_EMPTY_MESH", quoted(filename) + " has no faces" +
                             (polylines + points > 0 ? " (" + ignored + ")" : std::string()));
  if(statements.continued > 0)
    notes.push_back(std::to_string(statements.continued) +
                    " lines of the OBJ file end with a backslash: joined with the next line");
  if(polylines + points > 0) notes.push_back("OBJ file: " + ignored);
  if(statements.continued == 0 && polylines == 0) return; // CGAL reads the file as it is
  Obj_statements again(filename);
  while(again.next(line, number))
  {
    std::istringstream words(line);
    if(words >> keyword && keyword == "l") continue;
    normalized += line;
    normalized += '\n';
  }
}

} // namespace detail
} // namespace mesh_input
