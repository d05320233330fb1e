<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/ros/types.xsl - the ROS 1 / ROS 2 type of a typed model element,
  and the model's own data types a package declares and carries as
  generated messages (part of xslt/m2m/ros/psm.xsl).

  Reads:   typed elements of a bound PIM (@primitive, @type, @lower, @upper),
           pim:datatype, pim:enumeration; xslt/m2m/ros/types.xml and the
           user's type map ($fp:builtin-types, $fp:user-types of psm.xsl).
  Writes:  ty:type descriptions (values), r:types.
  Params:  none (ros-version of psm.xsl).  Keys: fp:id (psm-kit.xsl),
           fp:type-by-name, fp:type-by-primitive (psm.xsl).
  Errors:  ROS002 a default that does not fit its type;
           ROS010 a data type that contains itself.
  Warnings: ROS108 a bounded array in a ROS 1 message (ROS 1 has none: the
           field is unbounded, the bound is not enforced).
           ROS109 a data type no port carries with an attribute of a type
           the ROS type map cannot map: no header (the atomic code declares it).
           ROS120 a data type named Stamped that a carried data type is or
           specialises, without the attributes stamp: Real and frameId:
           String: no std_msgs/Header, its attributes are ordinary fields.

  Stamped data: a carried data type that is or specialises (at any depth)
  a data type named Stamped with stamp: Real (seconds) and frameId: String
  is stamped (r:struct/@stamped, r:message/@stamped): its message begins
  with std_msgs/Header header, whose stamp and frame_id those two
  attributes fill (r:field/@header), instead of two fields of their own.

  Types (the first that applies)
    mapped     an entry of the type map for the element's type name, then
               for its primitive kind (user map first): its message, C++
               type and parameter types as the entry says
    library    a message of a ROS library (type-library ros-message,
               type-name package/Name): that message, the datum itself
    struct     a UML DataType no entry maps: the C++ struct ::<pkg>::types::<Name> of the
               generated include/<Name>.hpp (m2t/common/data-types.xsl, the
               same header the Orocos target writes), carried as the
               generated message <Name> (msg/<Name>.msg: one field per
               attribute, inherited ones first)
    enum       a UML Enumeration with a literal: a plain enum ::<pkg>::types::<Name>,
               carried as the generated message <Name>: one int32 constant
               per literal (its number: its position) and the field value
    sequence   a multiplicity other than 1: std::vector of the element
               type; in a message field element[n] (fixed), element[<=n]
               (bounded: ROS 2; ROS 1 has no bound, ROS108), element[]
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:ty="urn:robomda:ros-types:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    exclude-result-prefixes="#all">

  <!-- the type of $typed, or () when the ROS targets cannot carry it -->
  <xsl:function name="fp:type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="single" as="element(ty:type)?" select="fp:single-type($typed)"/>
    <xsl:variable name="array" as="xs:string*" select="fp:array($typed)"/>
    <xsl:sequence select="if (empty($array)) then $single
                          else if (empty($single) or $single/@cpp eq 'void') then ()
                          else fp:sequence-type($single, $array)"/>
  </xsl:function>

  <xsl:function name="fp:single-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="name" as="xs:string" select="string($typed/@type-name)"/>
    <xsl:variable name="primitive" as="xs:string" select="string($typed/@primitive)"/>
    <xsl:sequence select="(
        if ($name ne '' and exists($fp:user-types)) then key('fp:type-by-name', $name, $fp:user-types) else (),
        if ($primitive ne '' and exists($fp:user-types)) then key('fp:type-by-primitive', $primitive, $fp:user-types) else (),
        if ($name ne '') then key('fp:type-by-name', $name, $fp:builtin-types) else (),
        if ($primitive ne '') then key('fp:type-by-primitive', $primitive, $fp:builtin-types) else (),
        if (fp:type-library($typed) eq 'ros-message') then fp:library-message($name) else (),
        fp:type-def($typed) ! fp:def-type(.))[1]"/>
  </xsl:function>

  <!-- a message of a ROS library the model names (type-library
       ros-message: Papyrus for Robotics' ROS 2 library), package/Name: the
       datum is the message itself, as a port's datum and as a field of a
       generated message (@element-kind message: copied as it is; @include:
       its header, which the data type's header includes) -->
  <xsl:function name="fp:library-message" as="element(ty:type)?">
    <xsl:param name="name" as="xs:string"/>
    <xsl:if test="matches($name, '^[A-Za-z][A-Za-z0-9_]*/[A-Za-z][A-Za-z0-9_]*$')">
      <xsl:variable name="package" as="xs:string" select="substring-before($name, '/')"/>
      <xsl:variable name="type" as="xs:string" select="substring-after($name, '/')"/>
      <xsl:variable name="cpp" as="xs:string"
          select="$package || (if ($ros-version eq '2') then '::msg::' else '::') || $type"/>
      <ty:type primitive="" cpp="{$cpp}" msg="{$name}" field="" msg-field="{$name}" param1="" param2="" sample="{$cpp}()"
               element-kind="message"
               include="{f:ros-header($package, $type, 'msg', $ros-version)}"/>
    </xsl:if>
  </xsl:function>

  <!-- a data type or an enumeration with a literal, as a generated type -->
  <xsl:function name="fp:def-type" as="element(ty:type)?">
    <xsl:param name="def" as="element()"/>
    <xsl:variable name="name" as="xs:string" select="f:cpp-identifier($def/@name)"/>
    <xsl:variable name="enum" as="xs:boolean" select="exists($def/self::pim:enumeration)"/>
    <xsl:variable name="msg" as="xs:string" select="f:upper-camel($def/@name)"/>
    <xsl:if test="not($enum) or exists($def/pim:literal)">
      <xsl:variable name="cpp" as="xs:string" select="fp:type-cpp-name($def, fp:package-name($package-name, root($def)/pim:model))"/>
      <ty:type kind="{if ($enum) then 'enum' else 'struct'}" primitive="" cpp="{$cpp}" msg="{$msg}" field=""
               msg-field="{$msg}" param1="" param2="" header="{$name}.hpp" type-ref="{$def/@id}"
               sample="{if ($enum) then $cpp || '::' || f:cpp-identifier($def/pim:literal[1]/@name) else $cpp || '()'}"/>
    </xsl:if>
  </xsl:function>

  <xsl:function name="fp:sequence-type" as="element(ty:type)">
    <xsl:param name="element" as="element(ty:type)"/>
    <xsl:param name="array" as="xs:string+"/>
    <xsl:variable name="cpp" as="xs:string" select="'std::vector&lt;' || $element/@cpp || '&gt;'"/>
    <xsl:variable name="bound" as="xs:string"
        select="if ($array[1] eq 'fixed') then $array[2]
                else if ($array[1] eq 'bounded' and $ros-version eq '2') then '&lt;=' || $array[2] else ''"/>
    <ty:type kind="sequence" primitive="" cpp="{$cpp}" msg="{$element/@multi-array}" field="data"
             msg-field="{if ($element/@msg-field ne '') then $element/@msg-field || '[' || $bound || ']' else ''}"
             param1="" param2="" array="{$array[1]}" size="{$array[2]}"
             sample="{if ($array[1] eq 'fixed') then $cpp || '(' || $array[2] || ', ' || $element/@sample || ')' else $cpp || '()'}">
      <xsl:sequence select="$element/@type-ref, $element/@header"/>
      <xsl:sequence select="$element"/>
    </ty:type>
  </xsl:function>

  <!-- ====================================================== the types -->
  <!-- r:types of the package: the data types and enumerations the
       components use (ports, attributes, operations, and the types these
       use, and the operations of the interfaces they require), each before
       its users; a message for those a message of $messages carries (a
       port's, a service's: and those these hold); () when there is none -->
  <xsl:function name="fp:ros-types" as="element(r:types)?">
    <xsl:param name="components" as="element(pim:bound-component)*"/>
    <xsl:param name="messages" as="element(r:message)*"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="typed" as="element()*"
        select="$components ! (pim:data-port, fp:attributes(fp:owner(.)), fp:operations(fp:owner(.))/pim:parameter,
                               fp:interface-operations(pim:service-port[@role eq 'required'])/pim:parameter)"/>
    <xsl:variable name="defs" as="element()*" select="fp:data-types($typed ! fp:type-def(.), 'ROS010')"/>
    <xsl:variable name="carried" as="element()*"
        select="fp:type-closure(distinct-values($messages[@generated eq 'true']/@type) ! key('fp:id', ., $root))"/>
    <!-- the carried types as a set: whether a type is carried is one look-up, not a scan of them all -->
    <xsl:variable name="carried-set" as="map(xs:string, xs:boolean)" select="map:merge($carried ! map:entry(generate-id(.), true()))"/>
    <xsl:variable name="declared" as="element()*" select="$defs[map:contains($carried-set, generate-id(.)) or fp:declarable(.)]"/>
    <xsl:for-each select="$defs except $declared">
      <xsl:sequence select="f:warn('ROS109', string(@id), 'no header is generated for data type ''' || @name
          || ''': an attribute of it, at some depth, has a type the ROS type map cannot map; the atomic code must declare ::'
          || f:cpp-identifier(@name) || ' itself')"/>
    </xsl:for-each>
    <xsl:for-each select="($carried/self::pim:datatype ! fp:lineage(.))[@name eq 'Stamped'] except $carried[fp:stamped(.)] ! fp:lineage(.)">
      <xsl:sequence select="f:warn('ROS120', string(@id), 'data type ''Stamped'' has not both attributes stamp: Real'
          || ' and frameId: String (one value each): the messages of the data types that specialise it carry no'
          || ' std_msgs/Header, its attributes are ordinary fields')"/>
    </xsl:for-each>
    <xsl:if test="exists($declared)">
      <r:types>
        <xsl:for-each select="$declared">
          <xsl:variable name="type" as="element(ty:type)?" select="fp:def-type(.)"/>
          <xsl:variable name="message" as="xs:boolean" select="map:contains($carried-set, generate-id(.))"/>
          <xsl:element name="{if (self::pim:enumeration) then 'r:enum' else 'r:struct'}" namespace="urn:robomda:psm-ros:1">
            <xsl:attribute name="xmi-id" select="@id"/>
            <xsl:attribute name="name" select="@name"/>
            <xsl:attribute name="cpp-name" select="$type/@cpp"/>
            <xsl:attribute name="header" select="$type/@header"/>
            <xsl:if test="$message"><xsl:attribute name="message" select="$type/@msg"/></xsl:if>
            <xsl:if test="$message and fp:stamped(.)"><xsl:attribute name="stamped" select="'true'"/></xsl:if>
            <xsl:sequence select="fp:psm-doc(.)"/>
            <xsl:sequence select="if (self::pim:enumeration) then fp:ros-literals(.) else fp:ros-fields(., $message)"/>
          </xsl:element>
        </xsl:for-each>
      </r:types>
    </xsl:if>
  </xsl:function>

  <!-- the attributes stamp (Real) and frameId (String) of data type $def,
       one value each, when $def is or specialises a data type named
       Stamped that declares both (of the Stamped nearest in its lineage);
       else () -->
  <xsl:function name="fp:stamp-attributes" as="element(pim:attribute)*">
    <xsl:param name="def" as="element()"/>
    <xsl:variable name="stamped" as="element()?" select="$def/self::pim:datatype/fp:lineage(.)[self::pim:datatype][@name eq 'Stamped'][1]"/>
    <xsl:variable name="attributes" as="element(pim:attribute)*" select="$stamped ! fp:attributes($def)"/>
    <xsl:variable name="stamp" as="element(pim:attribute)?"
        select="$attributes[@name eq 'stamp'][@primitive eq 'float64'][empty(fp:array(.))][empty(fp:type-def(.))]"/>
    <xsl:variable name="frame" as="element(pim:attribute)?"
        select="$attributes[@name eq 'frameId'][@primitive eq 'string'][empty(fp:array(.))][empty(fp:type-def(.))]"/>
    <xsl:sequence select="if (exists($stamp) and exists($frame)
                              and exists(fp:attributes($stamped)[@name eq 'stamp']) and exists(fp:attributes($stamped)[@name eq 'frameId']))
                          then ($stamp, $frame) else ()"/>
  </xsl:function>

  <xsl:function name="fp:stamped" as="xs:boolean">
    <xsl:param name="def" as="element()"/>
    <xsl:sequence select="exists(fp:stamp-attributes($def))"/>
  </xsl:function>

  <!-- whether every attribute of a data type has a ROS type, at any depth -->
  <xsl:function name="fp:declarable" as="xs:boolean">
    <xsl:param name="def" as="element()"/>
    <xsl:sequence select="every $a in $def/self::pim:datatype/fp:attributes(.)
                          satisfies exists(fp:type($a)) and (every $d in fp:type-def($a) satisfies fp:declarable($d))"/>
  </xsl:function>

  <xsl:function name="fp:ros-literals" as="element(r:literal)*">
    <xsl:param name="enumeration" as="element(pim:enumeration)"/>
    <xsl:for-each select="$enumeration/pim:literal">
      <r:literal xmi-id="{@id}" name="{@name}" member="{f:cpp-identifier(@name)}" value="{position() - 1}"
                 constant="{upper-case(f:snake-case(@name))}"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the members of the struct of $datatype, with their C++ initialisers
       and, for a message, their message fields -->
  <xsl:function name="fp:ros-fields" as="element(r:field)*">
    <xsl:param name="datatype" as="element(pim:datatype)"/>
    <xsl:param name="message" as="xs:boolean"/>
    <xsl:for-each select="fp:attributes($datatype)">
      <xsl:variable name="what" as="xs:string" select="'attribute ''' || @name || ''' of data type ''' || $datatype/@name || ''''"/>
      <xsl:variable name="type" as="element(ty:type)" select="fp:required-type(., @id, $what)"/>
      <xsl:variable name="element" as="element(ty:type)" select="($type/ty:type, $type)[1]"/>
      <xsl:if test="$message and $element/@msg-field eq ''">
        <xsl:sequence select="f:fail('ROS001', @id, $what || ' has type ''' || fp:type-label(.)
            || ''', which the type map carries as a whole message, not as a message field')"/>
      </xsl:if>
      <xsl:if test="$message and $type/@array eq 'bounded' and $ros-version eq '1'">
        <xsl:sequence select="f:warn('ROS108', @id, $what || ' holds at most ' || $type/@size
            || ' values, but ROS 1 messages have no bounded arrays: its field is unbounded and the bound is not enforced')"/>
      </xsl:if>
      <r:field xmi-id="{@id}" name="{f:snake-case(@name)}" member="{f:cpp-identifier(@name)}" cpp-type="{$type/@cpp}"
               cpp-default="{fp:cpp-default(., $type)}">
        <xsl:if test="$message and . intersect fp:stamp-attributes($datatype)">
          <xsl:attribute name="header" select="if (@name eq 'stamp') then 'stamp' else 'frame_id'"/>
        </xsl:if>
        <xsl:if test="$type/@kind">
          <xsl:attribute name="type-kind" select="$type/@kind"/>
          <xsl:sequence select="$type/@type-ref"/>
        </xsl:if>
        <xsl:if test="$message">
          <xsl:attribute name="msg-field" select="$type/@msg-field"/>
          <xsl:attribute name="element-kind" select="($element/@kind, $element/@element-kind, 'primitive')[1]"/>
          <xsl:sequence select="$type/@array"/>
        </xsl:if>
        <xsl:sequence select="$element/@include"/>
        <xsl:sequence select="fp:psm-doc(.)"/>
      </r:field>
    </xsl:for-each>
  </xsl:function>

  <!-- ========================================================= defaults -->
  <!-- the C++ initialiser of $typed of type $type: its default, else the
       type's sample (a data type: its attributes' defaults) -->
  <xsl:function name="fp:cpp-default" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:variable name="id" as="xs:string" select="string($typed/@id)"/>
    <xsl:variable name="default" as="xs:string?" select="$typed/@default[normalize-space(.)]"/>
    <xsl:variable name="element" as="element(ty:type)" select="($type/ty:type, $type)[1]"/>
    <xsl:sequence select="
      if (empty($default)) then string($type/@sample)
      else if ($element/@kind eq 'struct')
      then f:fail('ROS002', $id, 'default ''' || $default || ''' of data type ''' || $typed/@type-name
                  || ''': the data type''s attributes give its value')
      else if ($type/@kind eq 'sequence')
      then $type/@cpp || '{' || string-join(fp:default-items($default, $typed, $id, 'ROS002') ! fp:cpp-item(., $element, $typed), ', ') || '}'
      else fp:cpp-item($default, $type, $typed)"/>
  </xsl:function>

  <!-- the C++ literal of one value: a primitive or an enumeration literal -->
  <xsl:function name="fp:cpp-item" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="
      if ($type/@kind eq 'enum')
      then $type/@cpp || '::' || f:cpp-identifier(fp:enum-literal($value, key('fp:id', $type/@type-ref, root($typed)), $typed/@id, 'ROS002')/@name)
      else fp:values($value, $type, $typed/@id)[1]"/>
  </xsl:function>
</xsl:stylesheet>
