<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/openrtm/types.xsl - the OpenRTM-aist type of a data port's
  datum, and the package's data types: C++ headers for the atomic code and
  an IDL of the types the data ports carry; the text of a structured
  configuration value (part of xslt/m2m/openrtm/psm.xsl).

  Reads:   typed elements of a bound PIM (@primitive, @type, @lower, @upper),
           pim:datatype, pim:enumeration; xslt/m2m/openrtm/types.xml.
  Writes:  ty:type descriptions (values), r:data-types, configuration texts.
  Params:  none.  Keys: fp:id (psm-kit.xsl), fp:type (psm.xsl).
  Errors:  RTM021 a data type that contains itself, or an attribute of one
                  whose type OpenRTM has none for;
           RTM022 a default of a data type's attribute that does not fit its type;
           RTM002 (the caller's code) a configuration value that does not fit
                  its type, or a string in it with a double quote, backslash
                  or line break.

  Port types (OpenRTM's data-port convention: a struct whose first member is
  "RTC::Time tm" and whose datum is "data"; the IDL is compiled by omniidl
  with BasicDataType.idl on its include path, as OpenRTM's own
  OPENRTM_IDLFLAGS do)
    primitive  a single primitive with a TimedXxx of BasicDataType.idl (types.xml)
    value      a single data type or enumeration (with a literal) D: the
               generated <pkg>::Timed<D> { RTC::Time tm; D data; }; a single
               64-bit integer: <pkg>::TimedLongLong / TimedULongLong
    sequence   any multiplicity other than 1 of one of these E: RTC::Timed<E>Seq
               of BasicDataType.idl for a primitive that has one, else the
               generated <pkg>::Timed<E>Seq { RTC::Time tm; sequence<E> data; }
  In a generated struct, a fixed array [n] is an IDL array (E member[n]),
  any other multiplicity a sequence (typedef sequence<E> <E>Seq). The C++
  of the atomic code is the model's (include/<Name>.hpp: struct ::<Name>
  with std::vector for every array, enum ::<Name>); the RT-Component converts
  between the two (include/<pkg>/<pkg>_types.h).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:ty="urn:robomda:openrtm-types:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    exclude-result-prefixes="#all">

  <!-- the type of one value of $typed (no multiplicity), or () -->
  <xsl:function name="fp:rtm-single-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="def" as="element()?" select="fp:type-def($typed)"/>
    <xsl:sequence select="if (exists($def)) then fp:rtm-def-type($def, $package)
                          else key('fp:type', string($typed/@primitive), $fp:types)[@primitive ne 'void']"/>
  </xsl:function>

  <!-- a data type, or an enumeration with a literal (IDL has no empty enum) -->
  <xsl:function name="fp:rtm-def-type" as="element(ty:type)?">
    <xsl:param name="def" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="name" as="xs:string" select="f:cpp-identifier($def/@name)"/>
    <xsl:variable name="enum" as="xs:boolean" select="exists($def/self::pim:enumeration)"/>
    <xsl:if test="not($enum) or exists($def/pim:literal)">
      <!-- the C++ type of every target (a generated type belongs to its package); the IDL one beside it -->
      <xsl:variable name="cpp" as="xs:string" select="fp:type-cpp-name($def, $package)"/>
      <ty:type kind="{if ($enum) then 'enum' else 'struct'}" primitive="" label="{$name}" idl="::{$package}::{$name}"
               cpp="{$cpp}" header="{$name}.hpp" type-ref="{$def/@id}"
               sample="{if ($enum) then $cpp || '::' || f:cpp-identifier($def/pim:literal[1]/@name) else $cpp || '()'}"/>
    </xsl:if>
  </xsl:function>

  <!-- the type of $typed with its multiplicity: a sequence type holds its element's -->
  <xsl:function name="fp:rtm-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="single" as="element(ty:type)?" select="fp:rtm-single-type($typed, $package)"/>
    <xsl:variable name="array" as="xs:string*" select="fp:array($typed)"/>
    <xsl:choose>
      <xsl:when test="empty($array) or empty($single)">
        <xsl:sequence select="$single"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="cpp" as="xs:string" select="'std::vector&lt;' || $single/@cpp || '&gt;'"/>
        <ty:type kind="sequence" primitive="" label="{$single/@label}Seq" idl="::{$package}::{$single/@label}Seq"
                 cpp="{$cpp}" array="{$array[1]}" size="{$array[2]}"
                 sample="{if ($array[1] eq 'fixed') then $cpp || '(' || $array[2] || ', ' || $single/@sample || ')' else $cpp || '()'}">
          <xsl:sequence select="$single/@type-ref, $single/@header"/>
          <xsl:sequence select="$single"/>
        </ty:type>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- the attributes of an r:data-port for the type of its datum: the port's
       Timed type, how the datum converts (primitive: .data as it is; value,
       sequence: through <pkg>_types.h), the C++ type of the atomic code -->
  <xsl:function name="fp:rtm-port-type" as="attribute()*">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="type" as="element(ty:type)?" select="fp:rtm-type($typed, $package)"/>
    <xsl:variable name="element" as="element(ty:type)?" select="($type/ty:type, $type)[1]"/>
    <xsl:if test="exists($type)">
      <xsl:attribute name="timed" select="
          if ($type/@timed) then $type/@timed
          else if ($type/@kind eq 'sequence' and $element/@timed-seq) then $element/@timed-seq
          else $package || '::Timed' || $type/@label"/>
      <xsl:attribute name="cpp" select="$type/@cpp"/>
      <xsl:attribute name="primitive" select="$type/@primitive"/>
      <xsl:attribute name="convert" select="if ($type/@timed) then 'primitive' else if ($type/@kind eq 'sequence') then 'sequence' else 'value'"/>
    </xsl:if>
  </xsl:function>

  <!-- ====================================================== the types -->
  <!-- r:data-types of the package: a header for each data type and
       enumeration the components use (ports, attributes, operations, and
       the types these use), each before its users; in the IDL (@idl) those
       the data ports carry, with the sequences and Timed types the ports
       and fields need; () when the package needs none -->
  <xsl:function name="fp:rtm-data-types" as="element(r:data-types)?">
    <xsl:param name="components" as="element(pim:bound-component)*"/>
    <xsl:param name="ports" as="element(r:data-port)*"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="typed" as="element()*"
        select="$components ! (pim:data-port, fp:attributes(fp:owner(.)), fp:operations(fp:owner(.))/pim:parameter)"/>
    <xsl:variable name="defs" as="element()*"
        select="fp:data-types($typed ! fp:type-def(.), 'RTM021')[self::pim:datatype or pim:literal]"/>
    <!-- the ports whose data is converted, as a set: a look-up per data
         port, not a comparison with every port (quadratic, issue 35) -->
    <xsl:variable name="converted" as="map(xs:string, xs:boolean)"
        select="map:merge($ports[@convert ne 'primitive']/@xmi-id ! map:entry(string(.), true()))"/>
    <xsl:variable name="port-data" as="element(pim:data-port)*"
        select="$components/pim:data-port[@port ! map:contains($converted, string(.))]"/>
    <xsl:variable name="carried" as="element()*" select="fp:type-closure($port-data/fp:type-def(.))"/>
    <xsl:variable name="carried-set" as="map(xs:string, xs:boolean)" select="map:merge($carried ! map:entry(generate-id(.), true()))"/>
    <xsl:if test="exists($defs) or exists($port-data)">
      <!-- every typed element the IDL declares: the carried types' fields, the ports' data -->
      <xsl:variable name="fields" as="element(r:field)*"
          select="$defs[map:contains($carried-set, generate-id(.))]/self::pim:datatype ! fp:rtm-fields(., $package, true())"/>
      <!-- those fields by their struct: a look-up per struct, not a scan
           of every field (quadratic, issue 35) -->
      <xsl:variable name="fields-of" as="map(xs:string, element(r:field)*)">
        <xsl:map>
          <xsl:for-each-group select="$fields" group-by="string(@owner)">
            <xsl:map-entry key="current-grouping-key()" select="current-group()"/>
          </xsl:for-each-group>
        </xsl:map>
      </xsl:variable>
      <r:data-types idl="{$package}_types" module="{$package}">
        <xsl:for-each select="$defs">
          <xsl:variable name="type" as="element(ty:type)" select="fp:rtm-def-type(., $package)"/>
          <xsl:variable name="idl" as="xs:boolean" select="map:contains($carried-set, generate-id(.))"/>
          <xsl:element name="{if (self::pim:enumeration) then 'r:enum' else 'r:struct'}" namespace="urn:robomda:psm-openrtm:1">
            <xsl:attribute name="xmi-id" select="@id"/>
            <xsl:attribute name="name" select="@name"/>
            <xsl:attribute name="cpp-name" select="$type/@cpp"/>
            <xsl:attribute name="idl-name" select="$type/@label"/>
            <xsl:attribute name="header" select="$type/@header"/>
            <xsl:attribute name="idl" select="$idl"/>
            <xsl:sequence select="fp:psm-doc(.)"/>
            <xsl:for-each select="self::pim:enumeration/pim:literal">
              <r:literal xmi-id="{@id}" name="{@name}" member="{f:cpp-identifier(@name)}" value="{position() - 1}"/>
            </xsl:for-each>
            <xsl:sequence select="if ($idl) then $fields-of(string(@id)) else self::pim:datatype ! fp:rtm-fields(., $package, false())"/>
          </xsl:element>
        </xsl:for-each>
        <!-- the sequences the IDL's fields and generated Timed types hold, by name -->
        <xsl:variable name="port-types" as="element(ty:type)*" select="$port-data ! fp:rtm-type(., $package)"/>
        <xsl:for-each-group select="$fields[@convert eq 'sequence'], $port-types[@kind eq 'sequence'][empty(ty:type/@timed-seq)]"
            group-by="string((@idl-type, @idl)[1])">
          <xsl:sort select="current-grouping-key()"/>
          <xsl:variable name="element" as="xs:string" select="(@element-idl, ty:type/@idl)[1]"/>
          <r:sequence idl-name="{tokenize(current-grouping-key(), '::')[last()]}" element-idl="{$element}"/>
        </xsl:for-each-group>
        <xsl:for-each-group select="$port-types[@kind ne 'sequence' or empty(ty:type/@timed-seq)][empty(@timed)]" group-by="string(@label)">
          <xsl:sort select="current-grouping-key()"/>
          <r:timed idl-name="Timed{current-grouping-key()}" data-idl="{@idl}"/>
        </xsl:for-each-group>
      </r:data-types>
    </xsl:if>
  </xsl:function>

  <!-- the members of the struct of $datatype: their C++ (the header) and,
       for a struct in the IDL ($idl), their IDL declaration and conversion -->
  <xsl:function name="fp:rtm-fields" as="element(r:field)*">
    <xsl:param name="datatype" as="element(pim:datatype)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="idl" as="xs:boolean"/>
    <xsl:for-each select="fp:attributes($datatype)">
      <xsl:variable name="type" as="element(ty:type)" select="fp:rtm-field-type(., $datatype, $package)"/>
      <xsl:variable name="element" as="element(ty:type)?" select="($type/ty:type, $type)[1]"/>
      <r:field xmi-id="{@id}" owner="{$datatype/@id}" name="{@name}" member="{f:cpp-identifier(@name)}" cpp-type="{$type/@cpp}"
               cpp-default="{fp:rtm-cpp-default(., $type)}">
        <xsl:if test="$type/@kind = ('struct', 'enum', 'sequence')">
          <xsl:attribute name="type-kind" select="$type/@kind"/>
          <xsl:sequence select="$type/@type-ref"/>
        </xsl:if>
        <xsl:sequence select="fp:rtm-conf-bounds($type)"/>
        <xsl:if test="$idl">
          <xsl:attribute name="idl-type" select="if ($type/@array eq 'fixed') then $element/@idl else $type/@idl"/>
          <xsl:attribute name="element-idl" select="$element/@idl"/>
          <xsl:if test="$type/@array eq 'fixed'"><xsl:attribute name="idl-size" select="$type/@size"/></xsl:if>
          <xsl:attribute name="convert" select="if ($type/@array eq 'fixed') then 'array' else if ($type/@kind eq 'sequence') then 'sequence' else 'value'"/>
        </xsl:if>
        <xsl:sequence select="fp:psm-doc(.)"/>
      </r:field>
    </xsl:for-each>
  </xsl:function>

  <!-- the type of an attribute of data type $datatype; RTM021 when OpenRTM has none -->
  <xsl:function name="fp:rtm-field-type" as="element(ty:type)">
    <xsl:param name="attribute" as="element()"/>
    <xsl:param name="datatype" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:sequence select="(fp:rtm-type($attribute, $package),
        f:fail('RTM021', $attribute/@id, 'attribute ''' || $attribute/@name || ''' of data type ''' || $datatype/@name || ''' has type '''
               || fp:type-label($attribute) || '''' || fp:library-note($attribute) || ', which has no C++ / IDL type on OpenRTM (an enumeration needs a literal)'))[1]"/>
  </xsl:function>

  <!-- ================================================ configuration values -->
  <!-- how many items an array of $type holds, for <pkg>_conf.h to check:
       @array (fixed, bounded, unbounded) and @size; @element, the C++ type
       of one item; nothing for a single value -->
  <xsl:function name="fp:rtm-conf-bounds" as="attribute()*">
    <xsl:param name="type" as="element(ty:type)?"/>
    <xsl:if test="$type/@kind eq 'sequence'">
      <xsl:attribute name="array" select="$type/@array"/>
      <xsl:sequence select="$type/@size[. ne '']"/>
      <xsl:attribute name="element" select="$type/ty:type/@cpp"/>
    </xsl:if>
  </xsl:function>

  <!-- the text of the value $value (() = the one the model gives: a data
       type's attributes' defaults, an enumeration's first literal, a
       primitive's zero) of $typed, of the structured type $type, as a
       configuration value of OpenRTM (a .conf file, RTC.xml, the RtsProfile)
       that the generated <pkg>_conf.h reads: an array [a, b], a data type
       {name: value, ...} (every attribute, in order), an enumeration its
       literal's name, a string or character in double quotes, a number or
       Boolean as written. The same values as the other targets' deployment
       files (issue 37); the list form is ROS's YAML flow style. A value
       that does not fit fails with $code, naming $id. -->
  <xsl:function name="fp:rtm-conf-text" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="value" as="xs:string?"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="element" as="element(ty:type)" select="($type/ty:type, $type)[1]"/>
    <xsl:sequence select="
      if (exists($value) and $element/@kind eq 'struct')
      then f:fail($code, $id, 'value ''' || $value || ''' of ' || (if ($type/@kind eq 'sequence') then 'an array of ' else '')
                  || 'data type ''' || $element/@label || ''': the data type''s attributes give its value')
      else if ($type/@kind eq 'sequence')
      then '[' || string-join(
             if (exists($value)) then fp:default-items($value, $typed, $id, $code) ! fp:rtm-conf-item(., $element, $typed, $id, $code)
             else if ($type/@array eq 'fixed') then (1 to xs:integer($type/@size)) ! fp:rtm-conf-item((), $element, $typed, $id, $code)
             else (), ', ') || ']'
      else fp:rtm-conf-item($value ! fp:default-items(., $typed, $id, $code), $type, $typed, $id, $code)"/>
  </xsl:function>

  <!-- one value of a single type: a data type's attributes, each by name -->
  <xsl:function name="fp:rtm-conf-item" as="xs:string">
    <xsl:param name="value" as="xs:string?"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="def" as="element()?" select="$type/@type-ref ! key('fp:id', ., root($typed))"/>
    <xsl:variable name="text" as="xs:string?"
        select="if ($type/@kind = ('struct', 'enum') or empty($value)) then ()
                else fp:parse-default($value, $type/@kind, $type/@primitive, $id, $code)"/>
    <xsl:sequence select="
      if ($type/@kind eq 'struct')
      then '{' || string-join(fp:attributes($def) ! (@name || ': ' || fp:rtm-conf-text(., fp:rtm-field-type(., $def, ''),
                  @default[normalize-space(.)], @id, 'RTM022')), ', ') || '}'
      else if ($type/@kind eq 'enum')
      then (if (exists($value)) then fp:enum-literal($value, $def, $id, $code) else $def/pim:literal[1])/@name
      else if (empty($value))
      then (if ($type/@kind = ('string', 'char')) then '&quot;&quot;' else if ($type/@kind eq 'boolean') then 'false'
            else if ($type/@kind eq 'real') then '0.0' else '0')
      else if ($type/@kind = ('string', 'char') and matches($text, '[&quot;\\&#10;&#13;]'))
      then f:fail($code, $id, 'value ''' || $value || ''' has a double quote, backslash or line break, which a structured'
                  || ' configuration value cannot hold')
      else if ($type/@kind eq 'char' and string-length($text) ne 1)
      then f:fail($code, $id, 'value ''' || $value || ''' is not a single character')
      else if ($type/@kind = ('string', 'char')) then '&quot;' || $text || '&quot;'
      else if ($type/@kind eq 'real') then fp:decimal($text)
      else $text"/>
  </xsl:function>

  <!-- ========================================================= defaults -->
  <!-- the C++ initialiser of $typed of type $type: its default, else the
       type's sample (a data type: its attributes' defaults) -->
  <xsl:function name="fp:rtm-cpp-default" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:variable name="default" as="xs:string?" select="$typed/@default[normalize-space(.)]"/>
    <xsl:variable name="element" as="element(ty:type)" select="($type/ty:type, $type)[1]"/>
    <!-- the items of the default (one for a single value: fp:default-items refuses a list for it) -->
    <xsl:variable name="items" as="xs:string*"
        select="if (empty($default) or $element/@kind eq 'struct') then ()
                else fp:default-items($default, $typed, string($typed/@id), 'RTM022') ! fp:rtm-cpp-item(., $element, $typed)"/>
    <xsl:sequence select="
      if (empty($default)) then string($type/@sample)
      else if ($element/@kind eq 'struct')
      then f:fail('RTM022', string($typed/@id), 'default ''' || $default || ''' of data type ''' || $typed/@type-name
                  || ''': the data type''s attributes give its value')
      else if ($type/@kind eq 'sequence') then $type/@cpp || '{' || string-join($items, ', ') || '}'
      else $items"/>
  </xsl:function>

  <!-- the C++ literal of one value: a primitive or an enumeration literal -->
  <xsl:function name="fp:rtm-cpp-item" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="id" as="xs:string" select="string($typed/@id)"/>
    <xsl:variable name="parsed" as="xs:string?"
        select="if ($type/@kind eq 'enum') then () else fp:parse-default($value, $type/@kind, $type/@primitive, $id, 'RTM022')"/>
    <xsl:sequence select="
      if ($type/@kind eq 'enum')
      then $type/@cpp || '::' || f:cpp-identifier(fp:enum-literal($value, key('fp:id', $type/@type-ref, root($typed)), $id, 'RTM022')/@name)
      else if ($type/@kind eq 'string') then fp:cpp-string($parsed)
      else if ($type/@kind eq 'char') then
        (if (string-length($parsed) eq 1) then string(string-to-codepoints($parsed))
         else f:fail('RTM022', $id, 'default ''' || $value || ''' is not a single character'))
      else if ($type/@kind eq 'real') then fp:decimal($parsed) || (if ($type/@primitive eq 'float32') then 'f' else '')
      else $parsed"/>
  </xsl:function>
</xsl:stylesheet>
