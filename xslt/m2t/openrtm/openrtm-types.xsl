<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-types.xsl - the IDL of the data types an OpenRTM
  package's data ports carry, and the C++ conversions between its types and
  the model's (part of xslt/m2t/openrtm/main.xsl).

  Reads:   r:data-types of the OpenRTM PSM (xslt/m2m/openrtm/types.xsl).
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
</xsl:stylesheet>
