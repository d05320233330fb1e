<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/naming.xsl - identifiers and name styles shared by the stages.

  Reads:   nothing (a function module, included by stage stylesheets).
  Writes:  nothing.
  Params:  none.
  Errors:  none.

  Functions (namespace f = urn:robomda:xslt:function)
    f:words($name)            the words of a UML name: split at non-alphanumerics
                              and at lower/digit -> upper and UPPER -> Upper-lower
                              boundaries ("GX1050Camera" -> GX1050, Camera;
                              "visionValue" -> vision, Value; "IOPort" -> IO, Port)
    f:cpp-identifier($name)   a valid C++ identifier keeping the name's case:
                              invalid characters -> "_", leading digit -> "n",
                              empty -> "unnamed", C++ keyword -> keyword + "_"
    f:name-identifier($name)  the same without the keyword escape, for names that
                              never become C++ (a process: its files, its deployer
                              name): "RTT" stays "RTT"
    f:snake-case($name)       lower snake_case identifier ("visionValue" -> vision_value)
    f:ros-header($package, $name, $kind, $version)  the C++ header of ROS message or
                              service (kind msg / srv) $package/$name: ROS 1
                              pkg/Name.h, ROS 2 pkg/kind/name.hpp with rosidl's
                              file name (UInt8 -> u_int8)
    f:upper-camel($name)      UpperCamelCase identifier ("vision value" -> VisionValue)
    f:upper-first($s)         first letter upper-cased, rest unchanged
    f:lower-first($s)         first letter lower-cased, rest unchanged
    f:is-cpp-identifier($s)   true when $s is a valid, non-keyword C++ identifier
    f:escape-cpp-keyword($s)  $s + "_" when $s is a C++ keyword (or reserved
                              name such as a leading "_" + upper letter)
    f:unique-names($names)    the names made unique in order: a repeated name
                              gets "_2", "_3" ... (first occurrence unchanged)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:cpp-keywords" as="xs:string+" select="(
    'alignas', 'alignof', 'and', 'and_eq', 'asm', 'auto', 'bitand', 'bitor',
    'bool', 'break', 'case', 'catch', 'char', 'char8_t', 'char16_t', 'char32_t',
    'class', 'compl', 'concept', 'const', 'consteval', 'constexpr', 'constinit',
    'const_cast', 'continue', 'co_await', 'co_return', 'co_yield', 'decltype',
    'default', 'delete', 'do', 'double', 'dynamic_cast', 'else', 'enum',
    'explicit', 'export', 'extern', 'false', 'float', 'for', 'friend', 'goto',
    'if', 'inline', 'int', 'long', 'mutable', 'namespace', 'new', 'noexcept',
    'not', 'not_eq', 'nullptr', 'operator', 'or', 'or_eq', 'private',
    'protected', 'public', 'register', 'reinterpret_cast', 'requires', 'return',
    'short', 'signed', 'sizeof', 'static', 'static_assert', 'static_cast',
    'struct', 'switch', 'template', 'this', 'thread_local', 'throw', 'true',
    'try', 'typedef', 'typeid', 'typename', 'union', 'unsigned', 'using',
    'virtual', 'void', 'volatile', 'wchar_t', 'while', 'xor', 'xor_eq',
    'final', 'override', 'RTT', 'std')"/>
  <!-- the same words as a set, for look-ups -->
  <xsl:variable name="fp:cpp-keyword-set" as="map(xs:string, xs:boolean)"
      select="map:merge($fp:cpp-keywords ! map:entry(., true()))"/>

  <xsl:function name="f:words" as="xs:string*">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:variable name="spaced" as="xs:string"
        select="replace(replace(string($name), '([a-z0-9])([A-Z])', '$1 $2'),
                        '([A-Z]+)([A-Z][a-z])', '$1 $2')"/>
    <xsl:sequence select="tokenize($spaced, '[^A-Za-z0-9]+')[. ne '']"/>
  </xsl:function>

  <xsl:function name="f:escape-cpp-keyword" as="xs:string">
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="if (map:contains($fp:cpp-keyword-set, $text)
                              or (starts-with($text, '_') and matches($text, '^_[A-Z_]')) or contains($text, '__'))
                          then $text || '_' else $text"/>
  </xsl:function>

  <xsl:function name="f:cpp-identifier" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <!-- letters and digits after a letter (the usual case): only the keyword check applies -->
    <xsl:sequence select="if (matches(string($name), '^[A-Za-z][A-Za-z0-9]*$')) then f:escape-cpp-keyword(string($name))
                          else fp:cpp-identifier-any($name)"/>
  </xsl:function>

  <xsl:function name="fp:cpp-identifier-any" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:sequence select="f:escape-cpp-keyword(f:name-identifier($name))"/>
  </xsl:function>

  <xsl:function name="f:name-identifier" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:variable name="clean" as="xs:string"
        select="replace(replace(normalize-space(string($name)), '[^A-Za-z0-9_]', '_'), '_{2,}', '_')"/>
    <xsl:sequence select="if ($clean = ('', '_')) then 'unnamed'
                          else if (matches($clean, '^[0-9]')) then 'n' || $clean
                          else $clean"/>
  </xsl:function>

  <xsl:function name="f:ros-header" as="xs:string">
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:sequence select="if ($version eq '1') then $package || '/' || $name || '.h'
                          else $package || '/' || $kind || '/' || lower-case(string-join(f:words($name), '_')) || '.hpp'"/>
  </xsl:function>

  <xsl:function name="f:snake-case" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:variable name="writer" as="xs:string*" select="f:words($name)"/>
    <xsl:sequence select="if (empty($writer)) then 'unnamed'
                          else f:cpp-identifier(lower-case(string-join($writer, '_')))"/>
  </xsl:function>

  <xsl:function name="f:upper-first" as="xs:string">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="upper-case(substring(string($text), 1, 1)) || substring(string($text), 2)"/>
  </xsl:function>

  <xsl:function name="f:lower-first" as="xs:string">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="lower-case(substring(string($text), 1, 1)) || substring(string($text), 2)"/>
  </xsl:function>

  <xsl:function name="f:upper-camel" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:variable name="writer" as="xs:string*"
        select="tokenize(string($name), '[^A-Za-z0-9]+')[. ne '']"/>
    <xsl:sequence select="if (empty($writer)) then 'Unnamed'
                          else f:cpp-identifier(string-join($writer ! f:upper-first(.), ''))"/>
  </xsl:function>

  <xsl:function name="f:is-cpp-identifier" as="xs:boolean">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="matches(string($text), '^[A-Za-z_][A-Za-z0-9_]*$')
                          and f:escape-cpp-keyword(string($text)) eq string($text)"/>
  </xsl:function>

  <!-- one pass: $seen counts the occurrences of each name so far -->
  <xsl:function name="f:unique-names" as="xs:string*">
    <xsl:param name="names" as="xs:string*"/>
    <xsl:iterate select="$names">
      <xsl:param name="seen" as="map(xs:string, xs:integer)" select="map{}"/>
      <xsl:variable name="connection" as="xs:integer" select="($seen(.), 0)[1]"/>
      <xsl:sequence select="if ($connection eq 0) then . else . || '_' || ($connection + 1)"/>
      <xsl:next-iteration>
        <xsl:with-param name="seen" select="map:put($seen, ., $connection + 1)"/>
      </xsl:next-iteration>
    </xsl:iterate>
  </xsl:function>
</xsl:stylesheet>
