<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/orocos/types.xsl - the Orocos RTT 2.10 type of a typed model
  element, and the typekit a package needs (part of xslt/m2m/orocos/psm.xsl).

  Reads:   typed elements of a bound PIM (@primitive, @type, @lower, @upper),
           pim:datatype, pim:enumeration; xslt/m2m/orocos/types.xml.
  Writes:  ty:type descriptions (values), o:types, o:value trees.
  Params:  none.  Keys: fp:id (psm-kit.xsl), fp:type (psm.xsl).
  Errors:  ORO001 a type Orocos cannot carry (names the element and type);
           ORO002 a default value that does not fit its type;
           ORO012 a data type that contains itself.

  Types
    primitive  the row of types.xml (RTT's own types; int16 / uint16 /
               octet as int / unsigned int, types.xml says why)
    struct     a UML DataType: the C++ struct ::<pkg>::types::<Name> declared in the
               generated include/<Name>.hpp, with its attributes (inherited
               ones first) as members initialised to their defaults; RTT
               type "/<pkg>/<Name>" (StructTypeInfo, members by boost
               serialization; qualified by the package as orogen's are)
    enum       a UML Enumeration: a plain enum ::<pkg>::types::<Name> in include/<Name>.hpp
               (RTT 2.10's EnumTypeInfo converts it to int implicitly, which
               an enum class does not; code names a literal <Name>::<LITERAL>);
               RTT type "/<pkg>/<Name>" (a literal's name in cpf XML and
               scripts, its number converts too)
    sequence   any multiplicity other than 1 ([n], [0..n], [*]): std::vector
               of the element type, RTT type "array" for double (RTT's own)
               else "/std/vector</<element>>" (SequenceTypeInfo; .ops names
               it std.vector<pkg.T>, whose constructor sizes a property
               before the script sets its elements); a fixed [n] has n
               elements from the start. No array of boolean: std::vector<bool>
               is no container of bool references, and RTT has no typekit for it.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:ty="urn:robomda:orocos-types:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    exclude-result-prefixes="#all">

  <!-- the type of $typed, or () when Orocos cannot carry it -->
  <xsl:function name="fp:oro-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="def" as="element()?" select="fp:type-def($typed)"/>
    <xsl:variable name="single" as="element(ty:type)?"
        select="if (exists($def)) then fp:oro-def-type($def) else key('fp:type', string($typed/@primitive), $fp:types)"/>
    <xsl:variable name="array" as="xs:string*" select="fp:array($typed)"/>
    <xsl:sequence select="if (empty($array)) then $single
                          else if ($single/@primitive = ('void', 'boolean')) then ()
                          else $single ! fp:oro-sequence-type(., $array)"/>
  </xsl:function>

  <xsl:function name="fp:oro-def-type" as="element(ty:type)?">
    <xsl:param name="def" as="element()"/>
    <xsl:variable name="name" as="xs:string" select="f:cpp-identifier($def/@name)"/>
    <xsl:variable name="enum" as="xs:boolean" select="exists($def/self::pim:enumeration)"/>
    <xsl:if test="not($enum) or exists($def/pim:literal)">
      <xsl:variable name="package" as="xs:string" select="fp:package-name($package-name, root($def)/pim:model)"/>
      <xsl:variable name="rtt" as="xs:string" select="'/' || $package || '/' || $name"/>
      <xsl:variable name="cpp" as="xs:string" select="fp:type-cpp-name($def, $package)"/>
      <ty:type kind="{if ($enum) then 'enum' else 'struct'}" primitive="" cpp="{$cpp}" rtt="{$rtt}"
               xml="{if ($enum) then 'string' else $rtt}" header="{$name}.hpp" type-ref="{$def/@id}"
               sample="{if ($enum) then $cpp || '::' || f:cpp-identifier($def/pim:literal[1]/@name) else $cpp || '()'}"
               xml-sample="" pass="{if ($enum) then 'value' else 'cref'}"/>
    </xsl:if>
  </xsl:function>

  <xsl:function name="fp:oro-sequence-type" as="element(ty:type)">
    <xsl:param name="element" as="element(ty:type)"/>
    <xsl:param name="array" as="xs:string+"/>
    <xsl:variable name="cpp" as="xs:string" select="'std::vector&lt;' || $element/@cpp || '&gt;'"/>
    <xsl:variable name="rtt" as="xs:string"
        select="if ($element/@rtt eq 'double') then 'array'
                else '/std/vector&lt;' || (if (starts-with($element/@rtt, '/')) then '' else '/') || $element/@rtt || '&gt;'"/>
    <!-- its name in .ops: RTT's type look-up reads "std.vector<pkg.T>" as "/std/vector</pkg/T>" -->
    <xsl:variable name="script" as="xs:string"
        select="if ($rtt eq 'array') then $rtt else translate(replace(substring($rtt, 2), '&lt;/', '&lt;'), '/', '.')"/>
    <ty:type kind="sequence" primitive="" cpp="{$cpp}" rtt="{$rtt}" xml="{$rtt}" script="{$script}" array="{$array[1]}" size="{$array[2]}"
             sample="{if ($array[1] eq 'fixed') then $cpp || '(' || $array[2] || ', ' || $element/@sample || ')' else $cpp || '()'}"
             xml-sample="" pass="cref">
      <xsl:sequence select="$element/@type-ref, $element/@header"/>
      <xsl:sequence select="$element"/>
    </ty:type>
  </xsl:function>

  <xsl:function name="fp:oro-required-type" as="element(ty:type)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:variable name="type" as="element(ty:type)?" select="fp:oro-type($typed)"/>
    <xsl:sequence select="if (exists($type) and ($type/@primitive ne 'void' or $what eq 'result'))
        then $type
        else f:fail('ORO001', $id, $what || ' has type ''' || fp:type-label($typed) || '''' || fp:library-note($typed)
                     || ', which robomda cannot map
 to an Orocos C++ / XML type (supported: '
                     || string-join($fp:types//ty:type[@primitive ne 'void']/@primitive, ', ')
                     || ', the model''s data types and enumerations with a literal, and arrays of these but boolean)')"/>
  </xsl:function>

  <!-- the attributes typed elements, as a PSM element's attributes -->
  <xsl:function name="fp:oro-typed" as="attribute()*">
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:attribute name="primitive" select="$type/@primitive"/>
    <xsl:attribute name="cpp-type" select="$type/@cpp"/>
    <xsl:if test="$type/@xml ne ''"><xsl:attribute name="xml-type" select="$type/@xml"/></xsl:if>
    <xsl:if test="$type/@kind">
      <xsl:attribute name="type-kind" select="$type/@kind"/>
      <xsl:sequence select="$type/@type-ref"/>
    </xsl:if>
  </xsl:function>

  <!-- ======================================================= the typekit -->
  <!-- o:types of the package: the data types the task contexts use (and
       those these use), each before its users, and every sequence type
       RTT does not know; () when there is none -->
  <xsl:function name="fp:oro-types" as="element(o:types)?">
    <xsl:param name="task-contexts" as="element(o:task-context)*"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="typed" as="element()*" select="$task-contexts//*[@type-kind]"/>
    <xsl:variable name="defs" as="element()*"
        select="fp:data-types(distinct-values($typed/@type-ref[. ne '']) ! key('fp:id', ., $root), 'ORO012')"/>
    <!-- each struct's fields, by the data type's id (a look-up, not a scan of every field) -->
    <xsl:variable name="fields-of" as="map(xs:string, element(o:field)*)"
        select="map:merge($defs/self::pim:datatype ! map:entry(string(@id), fp:oro-fields(.)))"/>
    <xsl:variable name="fields" as="element(o:field)*" select="$defs/self::pim:datatype ! $fields-of(string(@id))"/>
    <xsl:if test="exists($defs) or exists($typed[@type-kind eq 'sequence'])">
      <o:types typekit="{$package}-typekit">
        <xsl:for-each select="$defs">
          <xsl:variable name="type" as="element(ty:type)" select="fp:oro-def-type(.)"/>
          <xsl:choose>
            <xsl:when test="self::pim:enumeration">
              <o:enum xmi-id="{@id}" name="{@name}" cpp-name="{$type/@cpp}" rtt-name="{$type/@rtt}" header="{$type/@header}">
                <xsl:sequence select="fp:psm-doc(.)"/>
                <xsl:for-each select="pim:literal">
                  <o:literal xmi-id="{@id}" name="{@name}" member="{f:cpp-identifier(@name)}" value="{position() - 1}"/>
                </xsl:for-each>
              </o:enum>
            </xsl:when>
            <xsl:otherwise>
              <o:struct xmi-id="{@id}" name="{@name}" cpp-name="{$type/@cpp}" rtt-name="{$type/@rtt}" header="{$type/@header}">
                <xsl:sequence select="fp:psm-doc(.)"/>
                <xsl:sequence select="$fields-of(string(@id))"/>
              </o:struct>
            </xsl:otherwise>
          </xsl:choose>
        </xsl:for-each>
        <xsl:for-each-group select="($typed, $fields)[@type-kind eq 'sequence']" group-by="@cpp-type">
          <xsl:sort select="@xml-type"/>
          <xsl:if test="@xml-type ne 'array'">
            <o:sequence cpp-type="{@cpp-type}" rtt-name="{@xml-type}"/>
          </xsl:if>
        </xsl:for-each-group>
      </o:types>
    </xsl:if>
  </xsl:function>

  <!-- the members of the struct of $datatype, with their C++ initialisers -->
  <xsl:function name="fp:oro-fields" as="element(o:field)*">
    <xsl:param name="datatype" as="element(pim:datatype)"/>
    <xsl:for-each select="fp:attributes($datatype)">
      <xsl:variable name="type" as="element(ty:type)"
          select="fp:oro-required-type(., @id, 'attribute ''' || @name || ''' of data type ''' || $datatype/@name || '''')"/>
      <o:field xmi-id="{@id}" owner="{$datatype/@id}" name="{@name}" member="{f:cpp-identifier(@name)}"
               cpp-default="{fp:oro-value(., $type, @name, '')/@cpp-value}">
        <xsl:sequence select="fp:oro-typed($type)"/>
        <xsl:sequence select="fp:psm-doc(.)"/>
      </o:field>
    </xsl:for-each>
  </xsl:function>

  <!-- ============================================================ values -->
  <!-- the value of $typed (of type $type) the model gives: its default, or
       for a data type its attributes' defaults; as an o:value tree whose
       leaves hold the cpf XML, script and C++ forms; @cpp-value on every
       node. $path: the script path of the value below its property. -->
  <xsl:function name="fp:oro-value" as="element(o:value)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="path" as="xs:string"/>
    <xsl:variable name="id" as="xs:string" select="string(($typed/@id, $typed/@port, $typed/@holder)[1])"/>
    <xsl:variable name="default" as="xs:string?" select="$typed/@default[normalize-space(.)]"/>
    <xsl:choose>
      <xsl:when test="$type/@kind eq 'sequence'">
        <xsl:variable name="element" as="element(ty:type)" select="$type/ty:type"/>
        <xsl:variable name="items" as="element(o:value)*">
          <xsl:choose>
            <xsl:when test="exists($default) and $element/@kind eq 'struct'">
              <xsl:sequence select="f:fail('ORO002', $id, 'default ''' || $default || ''' of an array of data type '''
                  || $element/@rtt || ''': the data type''s attributes give its value')"/>
            </xsl:when>
            <xsl:when test="exists($default)">
              <xsl:for-each select="fp:default-items($default, $typed, $id, 'ORO002')">
                <xsl:sequence select="fp:oro-leaf(., $element, $typed, 'Element' || (position() - 1), $path || '[' || (position() - 1) || ']')"/>
              </xsl:for-each>
            </xsl:when>
            <xsl:when test="$type/@array eq 'fixed'">
              <xsl:for-each select="1 to xs:integer($type/@size)">
                <xsl:sequence select="fp:oro-item($typed, $element, 'Element' || (. - 1), $path || '[' || (. - 1) || ']')"/>
              </xsl:for-each>
            </xsl:when>
          </xsl:choose>
        </xsl:variable>
        <!-- @size and @script-type: the scripts size the array before they set its elements -->
        <o:value name="{$name}" xml-type="{$type/@xml}" path="{$path}" size="{count($items)}" script-type="{$type/@script}"
                 cpp-value="{if (exists($default)) then $type/@cpp || '{' || string-join($items ! string(@cpp-value), ', ') || '}'
                             else $type/@sample}">
          <xsl:sequence select="$items"/>
        </o:value>
      </xsl:when>
      <xsl:when test="$type/@kind eq 'struct'">
        <xsl:if test="exists($default)">
          <xsl:sequence select="f:fail('ORO002', $id, 'default ''' || $default || ''' of data type ''' || $type/@rtt
              || ''': the data type''s attributes give its value')"/>
        </xsl:if>
        <o:value name="{$name}" xml-type="{$type/@xml}" path="{$path}" cpp-value="{$type/@sample}">
          <xsl:for-each select="fp:attributes(key('fp:id', $type/@type-ref, root($typed)))">
            <xsl:sequence select="fp:oro-value(., fp:oro-required-type(., @id, 'attribute ''' || @name || ''''),
                                               @name, $path || '.' || f:cpp-identifier(@name))"/>
          </xsl:for-each>
        </o:value>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="if (exists($default)) then fp:oro-leaf($default, $type, $typed, $name, $path)
                              else fp:oro-item($typed, $type, $name, $path)"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- an element with no value of its own: a data type's attributes' values,
       else the type's zero -->
  <xsl:function name="fp:oro-item" as="element(o:value)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="path" as="xs:string"/>
    <xsl:sequence select="
      if ($type/@kind eq 'struct') then fp:oro-value(key('fp:id', $type/@type-ref, root($typed)), $type, $name, $path)
      else if ($type/@kind eq 'enum') then fp:oro-leaf(key('fp:id', $type/@type-ref, root($typed))/pim:literal[1]/@name, $type, $typed, $name, $path)
      else fp:oro-zero($type, $name, $path)"/>
  </xsl:function>

  <!-- a primitive's zero: the value a C++ member starts with; the scripts
       set it as the deployer XML does (the whole value, issue 37), so a
       member the model gives no default starts the same in every format -->
  <xsl:function name="fp:oro-zero" as="element(o:value)">
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="path" as="xs:string"/>
    <o:value name="{$name}" xml-type="{$type/@xml}" path="{$path}" value="{$type/@xml-sample}" cpp-value="{$type/@sample}">
      <xsl:if test="$type/@primitive ne 'char'">
        <xsl:attribute name="script-value" select="if ($type/@primitive eq 'string') then '&quot;&quot;'
            else if ($type/@primitive eq 'boolean') then 'false' else $type/@xml-sample"/>
      </xsl:if>
    </o:value>
  </xsl:function>

  <!-- a leaf value: a primitive or an enumeration literal -->
  <xsl:function name="fp:oro-leaf" as="element(o:value)">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="path" as="xs:string"/>
    <xsl:variable name="id" as="xs:string" select="string(($typed/@id, $typed/@port, $typed/@holder)[1])"/>
    <xsl:variable name="values" as="xs:string+"
        select="if ($type/@kind eq 'enum')
                then fp:enum-literal($value, key('fp:id', $type/@type-ref, root($typed)), $id, 'ORO002')
                     ! (string(@name), string(count(preceding-sibling::pim:literal)), $type/@cpp || '::' || f:cpp-identifier(@name))
                else fp:oro-values($value, $type, $id)"/>
    <o:value name="{$name}" xml-type="{$type/@xml}" path="{$path}" value="{$values[1]}" script-value="{$values[2]}"
             cpp-value="{$values[3]}">
      <xsl:if test="$type/@kind eq 'enum'"><xsl:attribute name="enum" select="'true'"/></xsl:if>
    </o:value>
  </xsl:function>
</xsl:stylesheet>
