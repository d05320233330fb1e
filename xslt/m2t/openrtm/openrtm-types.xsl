<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-types.xsl - the IDL of the data types an OpenRTM
  package's data ports carry, the C++ conversions between its types and
  the model's, and the reader of structured configuration values (part of
  xslt/m2t/openrtm/main.xsl).

  Reads:   r:data-types, r:component/r:parameter of the OpenRTM PSM
           (xslt/m2m/openrtm/types.xsl, psm.xsl).
  Writes:  strings:
             idl/<pkg>_types.idl     module <pkg>: each carried enumeration and
                                     struct (a fixed array an IDL array, any other
                                     a sequence typedef), the Timed<X> structs of the
                                     ports (RTC::Time tm first, then data: OpenRTM's
                                     data-port convention, BasicDataType.idl included)
             include/<pkg>/<pkg>_types.h  namespace <pkg>: toIdl / fromIdl for each
                                     carried type, toIdlSeq / fromIdlSeq for
                                     sequences, toIdlArray / fromIdlArray for
                                     fixed arrays (elements converted one by one)
             include/<pkg>/<pkg>_conf.h   namespace <pkg>::conf: read(in, out) for
                                     primitives, every data type (its attributes by
                                     name) and enumeration (its literals' names),
                                     readList (an array within its bounds); parse<T>
                                     and parseList<T, Lower, Upper>, the conversions
                                     bindParameter takes (when a component has a
                                     structured configuration parameter)
  Params:  none.  Errors: none.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:types-xsl" as="xs:string" select="'m2t/openrtm/openrtm-types.xsl'"/>

  <!-- idl/<pkg>_types.idl -->
  <xsl:function name="fp:rtm-types-idl" as="xs:string">
    <xsl:param name="d" as="element(r:data-types)"/>
    <xsl:variable name="guard" as="xs:string" select="upper-case($d/@idl) || '_IDL'"/>
    <xsl:variable name="defs" as="element()*" select="$d/(r:enum | r:struct)[xs:boolean(@idl)]"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:types-xsl, 'the data types of the data ports of model ''' || $d/../@model-name || '''', false()),
      '#ifndef ' || $guard, '#define ' || $guard, '',
      '// RTC::Time, the time stamp of OpenRTM''s data-port convention',
      '#include &quot;BasicDataType.idl&quot;', '',
      'module ' || $d/@module, '{',
      fp:rtm-idl-sequences($d/r:sequence[not(starts-with(@element-idl, '::'))]),
      for $def in $defs return (
        if ($def/self::r:enum)
        then '  enum ' || $def/@idl-name || ' { ' || string-join($def/r:literal/@member, ', ') || ' };'
        else ('  struct ' || $def/@idl-name, '  {',
              $def/r:field ! ('    ' || @idl-type || ' ' || @member || (@idl-size ! ('[' || . || ']')) || ';'),
              '  };'),
        fp:rtm-idl-sequences($d/r:sequence[@element-idl eq '::' || $d/@module || '::' || $def/@idl-name])),
      $d/r:timed ! ('  struct ' || @idl-name, '  {', '    RTC::Time tm;', '    ' || @data-idl || ' data;', '  };'),
      '};', '', '#endif'))"/>
  </xsl:function>

  <xsl:function name="fp:rtm-idl-sequences" as="xs:string*">
    <xsl:param name="sequences" as="element(r:sequence)*"/>
    <xsl:sequence select="$sequences ! ('  typedef sequence&lt;' || @element-idl || '&gt; ' || @idl-name || ';')"/>
  </xsl:function>

  <!-- include/<pkg>/<pkg>_types.h -->
  <xsl:function name="fp:rtm-types-convert" as="xs:string">
    <xsl:param name="d" as="element(r:data-types)"/>
    <xsl:variable name="pkg" as="xs:string" select="$d/@module"/>
    <xsl:variable name="guard" as="xs:string" select="upper-case($pkg || '_' || $d/@idl) || '_H'"/>
    <xsl:variable name="defs" as="element()*" select="$d/(r:enum | r:struct)[xs:boolean(@idl)]"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:types-xsl, 'conversions of the data ports'' types of model ''' || $d/../@model-name || '''', false()),
      '#ifndef ' || $guard, '#define ' || $guard, '',
      '#include &quot;' || $d/@idl || '.hh&quot;',
      $defs ! ('#include &quot;' || @header || '&quot;'),
      '#include &lt;cstddef&gt;', '#include &lt;string&gt;', '#include &lt;type_traits&gt;', '#include &lt;vector&gt;', '',
      'namespace ' || $pkg || ' {', '',
      '// a primitive or an enumeration: converted by value; a string: copied',
      'template &lt;class A, class B&gt; inline void toIdl(const A&amp; in, B&amp;&amp; out)',
      '{ out = static_cast&lt;typename std::decay&lt;B&gt;::type&gt;(in); }',
      'template &lt;class B&gt; inline void toIdl(const std::string&amp; in, B&amp;&amp; out) { out = in.c_str(); }',
      'template &lt;class A, class B&gt; inline void fromIdl(const A&amp; in, B&amp; out) { out = static_cast&lt;B&gt;(in); }',
      'template &lt;class A&gt; inline void fromIdl(const A&amp; in, std::string&amp; out)',
      '{ const char* text = in; out = text ? text : &quot;&quot;; }',
      '',
      '// an array of the model (std::vector) to and from an IDL sequence and a fixed IDL array',
      'template &lt;class A, class S&gt; inline void toIdlSeq(const std::vector&lt;A&gt;&amp; in, S&amp; out)',
      '{',
      '  out.length(static_cast&lt;CORBA::ULong&gt;(in.size()));',
      '  for (CORBA::ULong i = 0; i &lt; out.length(); ++i) toIdl(in[i], out[i]);',
      '}',
      'template &lt;class S, class B&gt; inline void fromIdlSeq(const S&amp; in, std::vector&lt;B&gt;&amp; out)',
      '{',
      '  out.resize(in.length());',
      '  for (CORBA::ULong i = 0; i &lt; in.length(); ++i) { B item; fromIdl(in[i], item); out[i] = item; }',
      '}',
      'template &lt;class A, class E, std::size_t N&gt; inline void toIdlArray(const std::vector&lt;A&gt;&amp; in, E (&amp;out)[N])',
      '{',
      '  for (std::size_t i = 0; i &lt; N; ++i) toIdl(i &lt; in.size() ? A(in[i]) : A(), out[i]);',
      '}',
      'template &lt;class E, std::size_t N, class B&gt; inline void fromIdlArray(const E (&amp;in)[N], std::vector&lt;B&gt;&amp; out)',
      '{',
      '  out.resize(N);',
      '  for (std::size_t i = 0; i &lt; N; ++i) { B item; fromIdl(in[i], item); out[i] = item; }',
      '}',
      for $def in $defs return ('', fp:rtm-convert-def($def, $pkg)),
      '',
      '}  // namespace ' || $pkg, '',
      '#endif  // ' || $guard))"/>
  </xsl:function>

  <!-- toIdl / fromIdl of one carried type -->
  <xsl:function name="fp:rtm-convert-def" as="xs:string+">
    <xsl:param name="def" as="element()"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:variable name="idl" as="xs:string" select="'::' || $pkg || '::' || $def/@idl-name"/>
    <xsl:variable name="suffix" as="map(xs:string, xs:string)" select="map { 'value': '', 'sequence': 'Seq', 'array': 'Array' }"/>
    <xsl:sequence select="
      if ($def/self::r:enum) then (
        'inline void toIdl(const ' || $def/@cpp-name || '&amp; in, ' || $idl || '&amp; out) { out = static_cast&lt;' || $idl || '&gt;(in); }',
        'inline void fromIdl(const ' || $idl || '&amp; in, ' || $def/@cpp-name || '&amp; out) { out = static_cast&lt;' || $def/@cpp-name || '&gt;(in); }')
      else (
        'inline void toIdl(const ' || $def/@cpp-name || '&amp; in, ' || $idl || '&amp; out)', '{',
        $def/r:field ! ('  toIdl' || $suffix(@convert) || '(in.' || @member || ', out.' || @member || ');'), '}',
        'inline void fromIdl(const ' || $idl || '&amp; in, ' || $def/@cpp-name || '&amp; out)', '{',
        $def/r:field ! ('  fromIdl' || $suffix(@convert) || '(in.' || @member || ', out.' || @member || ');'), '}')"/>
  </xsl:function>

  <!-- ================================================ configuration values -->
  <!-- include/<pkg>/<pkg>_conf.h: the reader of a structured configuration
       parameter's text (a data type, an enumeration, an array), for
       bindParameter and the component's report of a value that does not parse.
       No IDL: a parameter needs only the model's C++ types. -->
  <xsl:function name="fp:rtm-conf-header" as="xs:string">
    <xsl:param name="system" as="element(r:system)"/>
    <xsl:variable name="pkg" as="xs:string" select="$system/@package"/>
    <xsl:variable name="defs" as="element()*" select="$system/r:data-types/(r:enum | r:struct)"/>
    <xsl:variable name="guard" as="xs:string" select="upper-case($pkg || '_' || $pkg) || '_CONF_H'"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:types-xsl, 'the configuration values of model ''' || $system/@model-name || '''', false()),
      '#ifndef ' || $guard, '#define ' || $guard, '',
      $defs ! ('#include &quot;' || @header || '&quot;'),
      ('cerrno', 'cmath', 'cstddef', 'cstdlib', 'cstring', 'limits', 'string', 'type_traits', 'vector') ! ('#include &lt;' || . || '&gt;'), '',
      'namespace ' || $pkg || ' {', 'namespace conf {', '',
      '// The text of a structured configuration parameter''s value (docs/openrtm.md): an array',
      '// [a, b, ...], a data type {attribute: value, ...}, an enumeration its literal''s name, a',
      '// string or character in double quotes, a number or Boolean as written. A value that does',
      '// not parse is refused, and OpenRTM''s ConfigAdmin sets the parameter to its default.',
      '',
      fp:rtm-text-lines($fp:rtm-conf-reader),
      for $def in $defs return ('', fp:rtm-conf-read($def)),
      '',
      fp:rtm-text-lines($fp:rtm-conf-parse),
      '',
      '}  // namespace conf',
      '}  // namespace ' || $pkg, '',
      '#endif  // ' || $guard))"/>
  </xsl:function>

  <!-- read(in, out) of one data type (its attributes by name) or enumeration (its literals' names) -->
  <xsl:function name="fp:rtm-conf-read" as="xs:string+">
    <xsl:param name="def" as="element()"/>
    <xsl:sequence select="'inline bool read(Reader&amp; in, ' || $def/@cpp-name || '&amp; out)', '{',
      if ($def/self::r:enum) then (
        '  const std::string name = in.word();',
        $def/r:literal ! ('  if (name == ' || fp:cpp-string(@name) || ') { out = ' || $def/@cpp-name || '::' || @member || '; return true; }'),
        '  return false;')
      else (
        '  return readFields(in, [&amp;in, &amp;out](const std::string&amp; name) {',
        $def/r:field ! ('    if (name == ' || fp:cpp-string(@name) || ') return '
          || (if (@array) then 'readList(in, out.' || @member || ', ' || string-join(fp:rtm-conf-limits(., ''), ', ') || ')'
              else 'read(in, out.' || @member || ')') || ';'),
        '    return false;',
        '  });'),
      '}'"/>
  </xsl:function>

  <!-- the least and the most items of an array (@array, @size), in C++;
       $scope: where the constant "unbounded" is ('' inside namespace conf) -->
  <xsl:function name="fp:rtm-conf-limits" as="xs:string+">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="scope" as="xs:string"/>
    <xsl:sequence select="if ($e/@array eq 'fixed') then ($e/@size, $e/@size)
                          else ('0', if ($e/@array eq 'bounded') then $e/@size else $scope || 'unbounded')"/>
  </xsl:function>

  <xsl:function name="fp:rtm-text-lines" as="xs:string*">
    <xsl:param name="text" as="xs:string"/>
    <xsl:variable name="lines" as="xs:string*" select="tokenize($text, '&#10;')"/>
    <xsl:sequence select="$lines[position() gt 1 and position() lt last()]"/>
  </xsl:function>

  <!-- the fixed part of <pkg>_conf.h: a cursor over the text, the reading of
       primitives, arrays and data types -->
  <xsl:variable name="fp:rtm-conf-reader" as="xs:string"><xsl:text>
/// the most items an unbounded array holds
constexpr std::size_t unbounded = static_cast&lt;std::size_t&gt;(-1);

/// a cursor over the text of a configuration value
struct Reader
{
  const char* at;
  void blank() { while (*at == ' ' || *at == '\t') ++at; }
  bool take(char c) { blank(); if (*at != c) return false; ++at; return true; }
  bool ends() { blank(); return *at == '\0'; }
  /// a number, a name or a Boolean: up to a blank or one of , : ] }
  std::string word()
  {
    blank();
    const char* from = at;
    while (*at != '\0' &amp;&amp; std::strchr(" \t,:]}", *at) == nullptr) ++at;
    return std::string(from, at);
  }
  /// a string: in double quotes, else a word
  bool text(std::string&amp; out)
  {
    blank();
    if (*at != '"') { out = word(); return true; }
    const char* from = ++at;
    while (*at != '\0' &amp;&amp; *at != '"') ++at;
    if (*at != '"') return false;
    out.assign(from, at++);
    return true;
  }
};

inline bool read(Reader&amp; in, bool&amp; out)
{
  const std::string word = in.word();
  if (word == "true" || word == "1") { out = true; return true; }
  if (word == "false" || word == "0") { out = false; return true; }
  return false;
}

inline bool read(Reader&amp; in, std::string&amp; out) { return in.text(out); }

inline bool read(Reader&amp; in, char&amp; out)
{
  std::string text;
  if (!in.text(text) || text.size() &gt; 1) return false;
  out = text.empty() ? '\0' : text[0];
  return true;
}

/// a number: the whole word, within the range of T
template &lt;class T&gt;
typename std::enable_if&lt;std::is_floating_point&lt;T&gt;::value, bool&gt;::type read(Reader&amp; in, T&amp; out)
{
  const std::string word = in.word();
  char* end = nullptr;
  errno = 0;
  const long double value = std::strtold(word.c_str(), &amp;end);
  if (word.empty() || *end != '\0' || errno == ERANGE || !(std::fabs(value) &lt;= std::numeric_limits&lt;T&gt;::max())) return false;
  out = static_cast&lt;T&gt;(value);
  return true;
}

template &lt;class T&gt;
typename std::enable_if&lt;std::is_integral&lt;T&gt;::value &amp;&amp; std::is_signed&lt;T&gt;::value &amp;&amp; !std::is_same&lt;T, char&gt;::value, bool&gt;::type
read(Reader&amp; in, T&amp; out)
{
  const std::string word = in.word();
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(word.c_str(), &amp;end, 10);
  const T narrowed = static_cast&lt;T&gt;(value);
  if (word.empty() || *end != '\0' || errno == ERANGE || static_cast&lt;long long&gt;(narrowed) != value) return false;
  out = narrowed;
  return true;
}

template &lt;class T&gt;
typename std::enable_if&lt;std::is_integral&lt;T&gt;::value &amp;&amp; std::is_unsigned&lt;T&gt;::value &amp;&amp; !std::is_same&lt;T, bool&gt;::value
                        &amp;&amp; !std::is_same&lt;T, char&gt;::value, bool&gt;::type
read(Reader&amp; in, T&amp; out)
{
  const std::string word = in.word();
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(word.c_str(), &amp;end, 10);
  const T narrowed = static_cast&lt;T&gt;(value);
  if (word.empty() || word[0] == '-' || *end != '\0' || errno == ERANGE
      || static_cast&lt;unsigned long long&gt;(narrowed) != value) return false;
  out = narrowed;
  return true;
}

/// an array: [item, ...] with at least lower and at most upper items
template &lt;class T&gt;
bool readList(Reader&amp; in, std::vector&lt;T&gt;&amp; out, std::size_t lower, std::size_t upper)
{
  std::vector&lt;T&gt; items;
  if (!in.take('[')) return false;
  if (!in.take(']'))
  {
    do
    {
      T item = T();
      if (!read(in, item)) return false;
      items.push_back(item);
    } while (in.take(','));
    if (!in.take(']')) return false;
  }
  if (items.size() &lt; lower || items.size() &gt; upper) return false;
  out.swap(items);
  return true;
}

/// a data type: {name: value, ...}; field(name) reads the value of the attribute name
template &lt;class Field&gt;
bool readFields(Reader&amp; in, Field field)
{
  if (!in.take('{')) return false;
  if (in.take('}')) return true;
  do
  {
    const std::string name = in.word();
    if (name.empty() || !in.take(':') || !field(name)) return false;
  } while (in.take(','));
  return in.take('}');
}
</xsl:text></xsl:variable>

  <!-- the entries bindParameter calls: the whole text as one value -->
  <xsl:variable name="fp:rtm-conf-parse" as="xs:string"><xsl:text>
/// the whole text as a value of T (a data type: the attributes it does not name keep the model's defaults)
template &lt;class T&gt;
bool parse(T&amp; out, const char* text)
{
  if (text == nullptr) return false;
  Reader in{text};
  T value = T();
  if (!read(in, value) || !in.ends()) return false;
  out = value;
  return true;
}

/// the whole text as an array of Lower to Upper items; also without brackets ("1, 2, 3"), as
/// OpenRTM's own examples write a vector parameter
template &lt;class T, std::size_t Lower, std::size_t Upper&gt;
bool parseList(std::vector&lt;T&gt;&amp; out, const char* text)
{
  if (text == nullptr) return false;
  Reader probe{text};
  const std::string list = probe.take('[') ? std::string(text) : "[" + std::string(text) + "]";
  Reader in{list.c_str()};
  std::vector&lt;T&gt; value;
  if (!readList(in, value, Lower, Upper) || !in.ends()) return false;
  out.swap(value);
  return true;
}
</xsl:text></xsl:variable>
</xsl:stylesheet>
