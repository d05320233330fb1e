<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-types.xsl - the RTT typekit of an Orocos package:
  src/typekit.cpp registers the model's data types, enumerations and the
  sequences of them RTT does not know, so that their ports connect, their
  properties load from deployer XML and .cpf files and scripts read and
  write them (RTT 2.10, no orogen / typegen).

  Reads:   o:types of urn:robomda:psm-orocos:1.
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  struct    RTT::types::StructTypeInfo<T>: its members by name, through a
            boost::serialization serialize() function written here (the
            type is the model's, so the function is not intrusive)
  enum      RTT::types::EnumTypeInfo<T> with the literals' names, so that
            cpf XML and scripts may use the names (RTT converts ints too)
  sequence  RTT::types::SequenceTypeInfo<std::vector<T>>
  RTT names are qualified by the package as orogen's are ("/<pkg>/T",
  "/std/vector</<pkg>/T>", "/std/vector</int>"; std::vector<double> is
  RTT's "array"), so that two packages that each define a T load into one
  deployer; scripts name them "<pkg>.T", "std.vector<<pkg>.T>".
  The typekit is loaded before the components (deploy files: LoadLibrary
  <pkg>/types/<pkg>-typekit).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:typekit-cpp" as="xs:string">
    <xsl:param name="types" as="element(o:types)"/>
    <xsl:variable name="ns" as="xs:string" select="$types/../@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:typekit-xsl, 'the RTT typekit of model ''' || $types/../@model-name || '''', false()),
        '#include &lt;rtt/types/TypekitPlugin.hpp&gt;',
        '#include &lt;rtt/types/Types.hpp&gt;',
        '#include &lt;rtt/types/TypeInfoRepository.hpp&gt;',
        if ($types/o:struct) then ('#include &lt;rtt/types/StructTypeInfo.hpp&gt;', '#include &lt;boost/serialization/nvp.hpp&gt;') else (),
        if ($types/o:sequence) then '#include &lt;rtt/types/SequenceTypeInfo.hpp&gt;' else (),
        if ($types/o:enum) then '#include &lt;rtt/types/EnumTypeInfo.hpp&gt;' else (),
        '#include &lt;string&gt;',
        '#include &lt;vector&gt;',
        ($types/o:struct, $types/o:enum) ! ('#include &quot;' || @header || '&quot;'),
        fp:typekit-serialize($types/o:struct),
        '',
        'namespace ' || $ns || ' {',
        $types/o:enum ! (
          '',
          '// enumeration ' || @name || ': its literals by name (cpf XML, scripts)',
          'struct ' || replace(@cpp-name, '^.*::', '') || 'TypeInfo : public RTT::types::EnumTypeInfo&lt;' || @cpp-name || '&gt;',
          '{',
          '  ' || replace(@cpp-name, '^.*::', '') || 'TypeInfo() : RTT::types::EnumTypeInfo&lt;' || @cpp-name || '&gt;(&quot;' || @rtt-name || '&quot;)',
          '  {',
          o:literal ! ('    to_string[' || ../@cpp-name || '::' || @member || '] = &quot;' || @name || '&quot;;'),
          '  }',
          '};'),
        '',
        '/** The types of model ' || $types/../@model-name || ' in RTT''s type system. */',
        'class Typekit : public RTT::types::TypekitPlugin',
        '{',
        'public:',
        '  bool loadTypes()',
        '  {',
        '    RTT::types::TypeInfoRepository::shared_ptr types = RTT::types::Types();',
        $types/o:enum ! ('    types-&gt;addType(new ' || replace(@cpp-name, '^.*::', '') || 'TypeInfo());'),
        $types/o:struct ! ('    types-&gt;addType(new RTT::types::StructTypeInfo&lt;' || @cpp-name || '&gt;(&quot;' || @rtt-name || '&quot;));'),
        $types/o:sequence ! ('    types-&gt;addType(new RTT::types::SequenceTypeInfo&lt;' || @cpp-type || '&gt;(&quot;' || @rtt-name || '&quot;));'),
        '    return true;',
        '  }',
        '  bool loadOperators() { return true; }',
        '  bool loadConstructors() { return true; }',
        '  std::string getName() { return &quot;' || $types/@typekit || '&quot;; }',
        '};',
        '',
        '}  // namespace ' || $ns,
        '',
        'ORO_TYPEKIT_PLUGIN(' || $ns || '::Typekit)'))"/>
  </xsl:function>

  <!-- boost::serialization of each data type, for RTT::types::StructTypeInfo -->
  <xsl:function name="fp:typekit-serialize" as="xs:string*">
    <xsl:param name="structs" as="element(o:struct)*"/>
    <xsl:sequence select="
        if ($structs) then (
          '',
          '// the members of each data type by name, for RTT::types::StructTypeInfo',
          'namespace boost {',
          'namespace serialization {',
          $structs ! (
            '',
            'template &lt;class Archive&gt;',
            'void serialize(Archive&amp; archive, ' || @cpp-name || '&amp; value, const unsigned int)',
            '{',
            o:field ! ('  archive &amp; make_nvp(&quot;' || @name || '&quot;, value.' || @member || ');'),
            if (o:field) then () else '  (void)archive; (void)value;',
            '}'),
          '',
          '}  // namespace serialization',
          '}  // namespace boost') else ()"/>
  </xsl:function>
</xsl:stylesheet>
