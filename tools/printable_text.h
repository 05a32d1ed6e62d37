// Text that comes from a file or a path (file names, error messages that
// quote a file's bytes), made safe for JSON and for the terminal.
#ifndef UV_TOOLS_PRINTABLE_TEXT_H
#define UV_TOOLS_PRINTABLE_TEXT_H

#include <cstddef>
#include <string>

namespace cut_tools {

/// Returns `text` with every byte that is not part of a well-formed UTF-8
/// sequence (stray continuation bytes, overlong forms, surrogates, code
/// points above U+10FFFF, truncated sequences: a Latin-1 `é` is the byte
/// 0xE9) and every control character other than tab written as the four
/// characters `\xNN`; valid UTF-8 text is returned unchanged. The result is
/// valid UTF-8 and holds no line break or terminal escape sequence, so that
/// it can go into JSON (nlohmann-json refuses invalid UTF-8) and on one line
/// of a terminal.
inline std::string printable_text(const std::string& text)
{
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  auto escape = [&](unsigned char c) {
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
  };
  const std::size_t n = text.size();
  std::size_t i = 0;
  while(i < n)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c < 0x80)
    {
      if((c < 0x20 && c != '\t') || c == 0x7f) escape(c);
      else out += char(c);
      ++i;
      continue;
    }
    // length of the sequence and the range of its second byte (RFC 3629)
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xbf;
    if(c >= 0xc2 && c <= 0xdf) length = 2;
    else if(c == 0xe0) { length = 3; low = 0xa0; }
    else if(c == 0xed) { length = 3; high = 0x9f; }
    else if(c >= 0xe1 && c <= 0xef) length = 3;
    else if(c == 0xf0) { length = 4; low = 0x90; }
    else if(c >= 0xf1 && c <= 0xf3) length = 4;
    else if(c == 0xf4) { length = 4; high = 0x8f; }
    bool valid = length > 0 && i + length <= n;
    for(std::size_t k = 1; valid && k < length; ++k)
    {
      const unsigned char b = static_cast<unsigned char>(text[i + k]);
      valid = k == 1 ? (b >= low && b <= high) : (b >= 0x80 && b <= 0xbf);
    }
    if(!valid)
    {
      escape(c);
      ++i;
      continue;
    }
    // C1 control characters (U+0080..U+009F) start terminal escapes too
    if(c == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0)
    {
      escape(c);
      escape(static_cast<unsigned char>(text[i + 1]));
    }
    else
      out.append(text, i, length);
    i += length;
  }
  return out;
}

} // namespace cut_tools

#endif
