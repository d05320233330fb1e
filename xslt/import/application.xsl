<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/application.xsl - the application part of the PIM (component
  diagram, seed 000 Tables 1, 2 and 4).

  Reads:   the normalised XMI, from the model root (fp:model-root) down.
  Writes:  pim:package, pim:primitive, pim:datatype, pim:enumeration,
           pim:class, pim:interface, pim:component and what they hold
           (schemas/pim/1/pim.xsd); mode mp:packageable.
  Params:  none; tunnel parameters set by import.xsl: href-types
           (fp:href-types of the normalised XMI) reaches the mp:feature
           rules, root (the model root) every rule that writes a
           qualified name (fp:qname).
  Errors:  none raised here: the check pass (check.xsl) has reported every
           dangling reference before this runs.

  Rules (by UML metaclass, xmi:type or the feature's default type)
  - Package, Model (nested models too) -> pim:package. Contents: every
    child of a packageable metaclass, whatever the feature (packagedElement,
    ownedMember, ownedType, nestedClassifier, a Visual Paradigm deployment
    xmi:type="uml:Component"), and those of children the application does
    not write (Nodes, Artifacts, behaviours ...: fp:owned-packageables).
    Signal -> pim:datatype.
  - Deployment elements (Node, Device, ExecutionEnvironment, Artifact,
    DeploymentSpecification, CommunicationPath) are skipped here: they go
    to pim:platform wherever they are in the model (platform.xsl).
  - Class / Component / Interface: generalization (general; an href into
    another model is skipped), provides (InterfaceRealization owned by or
    with client = the classifier; EA <provided xmi:idref>; a generic
    Realization to an interface), requires (Usage with client = the
    classifier; EA <required xmi:idref>), attributes, ports, parts
    (composite Property typed by a Class or Component, owned by a class or
    component), operations, connectors.
  - Component realization: realization (ComponentRealization, realizing-
    Classifier, else its client) and EA's Realization class -> component.
  - Interfaces, usages and realizations that point into another model
    (href) have no PIM element to refer to and are not written.
  - Port: type (interface, class or data type; a protocol, i.e. a
    Collaboration, gives provided = the interfaces it realizes, required =
    those it uses, swapped when conjugated), explicit provided / required
    (EA children; Usage or InterfaceRealization whose client is the port;
    @via names the dependencies and the EA children), isConjugated,
    isService, isBehavior. An EA exposed interface that names no interface
    of the model is not imported (IMP119, report.xsl).
  - Typed elements: a type that is an element of the model the PIM has no
    element for (a behaviour, an actor ...) gives type-name and
    type-metaclass, no @type; warnings IMP101 (no type), IMP102 (not a
    type), IMP103 (a behaviour: a function of the owner).
  - Connector (an ownedConnector, or a connector anywhere else that joins
    parts of the classifier: fp:connector-owner): kind from @kind, else
    delegation when an end has no
    partWithPort and its role is a port of the connector's owner; ends with
    role and part (partWithPort), and the path of parts down to that part
    when it is a part of a part (SysML NestedConnectorEnd propertyPath, or
    the one chain of parts to a partWithPort: connector-ends.xsl). A
    connector with an end outside the model (href role), or with an end
    whose path cannot be followed, is not written.
  - Dependency (exactly xmi:type uml:Dependency, not Usage / Realization ...)
    marked as a deployment-sequence constraint (fp:is-start-after: the
    robomda stereotype StartAfter, else the name "startAfter", case-
    insensitive) -> pim:dependency with its clients (the parts that start
    later) and suppliers (the parts started first), in document order,
    wherever it is owned (package or classifier). A plain Dependency
    whose suppliers are Devices -> pim:dependency kind "drives" (its
    clients, parts or components, drive that hardware: the bind step
    checks their arrays against the Device's dof, seed 001). Every other
    plain Dependency carries no PIM content and is not written. Clients and
    suppliers in another model (href) are not written; a dependency left
    without a client or a supplier is not written (IMP111).
  - What is not written is named by a warning (report.xsl, IMP110-IMP116).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:mode name="mp:packageable" on-no-match="deep-skip"/>
  <xsl:mode name="mp:feature" on-no-match="deep-skip"/>

  <!-- the metaclasses mode mp:packageable writes to the PIM -->
  <xsl:variable name="packageable-metas" as="xs:string+"
      select="('Package', 'Model', 'PrimitiveType', 'DataType', 'Signal', 'Enumeration', 'Class',
               'Interface', 'Component', 'Dependency')"/>
  <!-- what never holds a packageable element robomda reads: features,
       relationships, values, profiles, template signatures and bindings
       (their placeholders, x:type TemplateParameter, are no classes) -->
  <xsl:variable name="leaf-metas" as="xs:string+"
      select="('Property', 'Port', 'Operation', 'Parameter', 'Connector', 'ConnectorEnd', 'Generalization',
               'Comment', 'Constraint', 'EnumerationLiteral', 'Association', 'Profile', 'Stereotype',
               'Extension', 'ProfileApplication', 'PackageImport', 'ElementImport', 'CommunicationPath',
               $dependency-metas, 'Abstraction', 'Dependency', 'InstanceSpecification', 'Slot',
               'TemplateSignature', 'RedefinableTemplateSignature', 'TemplateBinding', 'TemplateParameter')"/>

  <!-- the two lists as maps: one look-up per child element -->
  <xsl:variable name="packageable-map" as="map(xs:string, xs:boolean)"
      select="map:merge($packageable-metas ! map:entry(., true()))"/>
  <xsl:variable name="leaf-map" as="map(xs:string, xs:boolean)"
      select="map:merge(distinct-values($leaf-metas) ! map:entry(., true()))"/>

  <!-- the packageable elements owned by $e (a package or a classifier),
       found by metaclass whatever the feature that holds them
       (packagedElement, ownedMember, ownedType, nestedClassifier, a
       Visual Paradigm deployment xmi:type="uml:Component" ...), and those
       owned by an element the application does not write (a Node, an
       Artifact, an Activity, a Collaboration ...: EA nests components in
       Nodes), which keep their qualified name under that owner -->
  <xsl:function name="fp:owned-packageables" as="element()*">
    <xsl:param name="element" as="element()"/>
    <!-- an EA exposed interface (<provided>, <required>) is no interface
         of its own, whatever its xmi:type (dialect-ea.xsl) -->
    <xsl:for-each select="$element/*[@x:type][not(@href or @x:idref)][not(self::provided or self::required)]">
      <xsl:variable name="meta" as="xs:string" select="@x:type"/>
      <xsl:choose>
        <xsl:when test="map:contains($packageable-map, $meta)">
          <xsl:sequence select="."/>
        </xsl:when>
        <xsl:when test="not(map:contains($leaf-map, $meta))">
          <xsl:sequence select="fp:owned-packageables(.)"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- ========================================================= packages -->
  <xsl:template match="*[@x:type = ('Package', 'Model')]" mode="mp:packageable"
                as="element(pim:package)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:package id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:if test="@x:file"><xsl:attribute name="file" select="fp:uri-decode(@x:file)"/></xsl:if>
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:apply-templates select="fp:owned-packageables(.)" mode="mp:packageable"/>
    </pim:package>
  </xsl:template>

  <!-- ============================================== simple classifiers -->
  <xsl:template match="*[@x:type eq 'PrimitiveType']" mode="mp:packageable"
                as="element(pim:primitive)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:primitive id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
    </pim:primitive>
  </xsl:template>

  <!-- a Signal is a classifier of data: the PIM holds it as a datatype -->
  <xsl:template match="*[@x:type = ('DataType', 'Signal')]" mode="mp:packageable"
                as="element(pim:datatype)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:datatype id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:apply-templates select="generalization" mode="mp:feature"/>
      <xsl:apply-templates select="ownedAttribute[not(@x:type = 'Port')]" mode="mp:feature"/>
      <xsl:apply-templates select="ownedOperation" mode="mp:feature"/>
    </pim:datatype>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'Enumeration']" mode="mp:packageable"
                as="element(pim:enumeration)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:enumeration id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:for-each select="ownedLiteral">
        <pim:literal id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
          <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
        </pim:literal>
      </xsl:for-each>
    </pim:enumeration>
  </xsl:template>

  <!-- ====================================================== classifiers -->
  <xsl:template match="*[@x:type eq 'Class']" mode="mp:packageable" as="element(pim:class)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:class id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}"
        abstract="{fp:bool(@isAbstract, false())}" active="{fp:bool(@isActive, false())}">
      <!-- a component in its tool's own profile (dialects.xsl) -->
      <xsl:sequence select="fp:dialect-component(.)"/>
      <xsl:call-template name="tp:classifier-body"/>
      <xsl:apply-templates select="fp:owned-packageables(.)" mode="mp:packageable"/>
    </pim:class>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'Interface']" mode="mp:packageable" as="element(pim:interface)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:interface id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <!-- the communication pattern it binds in its tool's profile, or the
           message set of a UML-RT protocol it is -->
      <xsl:sequence select="fp:pattern-attributes(.), fp:message-attributes(.)"/>
      <xsl:call-template name="tp:classifier-body"/>
      <xsl:apply-templates select="fp:owned-packageables(.)" mode="mp:packageable"/>
    </pim:interface>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'Component']" mode="mp:packageable" as="element(pim:component)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:variable name="classifier" as="element()" select="."/>
    <pim:component id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}"
        abstract="{fp:bool(@isAbstract, false())}">
      <!-- owned by a Node (EA nests components in the node they run on;
           Visual Paradigm writes them as the node's deployments) -->
      <xsl:for-each select="ancestor::*[@x:type = $node-metas][1]">
        <xsl:attribute name="node" select="fp:id(.)"/>
      </xsl:for-each>
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:variable name="realizations" as="element()*"
          select="realization[@x:type eq 'ComponentRealization']
                  | key('fp:dep-by-supplier', fp:id(.))[@x:type eq 'ComponentRealization']
                    [not(../@x:type = 'Component')]
                  | fp:ea-realizations(.)"/>
      <xsl:for-each select="$realizations">
        <xsl:variable name="realization" as="element()" select="."/>
        <xsl:variable name="classifiers" as="element()*"
            select="if (exists(fp:ref-ids(., 'realizingClassifier')))
                    then fp:targets(., 'realizingClassifier')
                    else (fp:targets(., 'client') except $classifier,
                          fp:targets(., 'supplier') except $classifier)[1]"/>
        <!-- a realization of several components: each its own ids -->
        <xsl:variable name="id" as="xs:string" select="fp:id($classifier)"/>
        <xsl:variable name="sides" as="xs:string*"
            select="if (fp:ref-ids(., 'supplier') = $id) then fp:ref-ids(., 'supplier') else fp:ref-ids(., 'client')"/>
        <xsl:variable name="count" as="xs:integer" select="max((count(fp:ref-ids(., 'realizingClassifier')), 1))"/>
        <xsl:for-each select="$classifiers">
          <pim:realization id="{fp:pair-id($realization, $sides, $id, $count, position())}" classifier="{fp:id(.)}"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:call-template name="tp:classifier-body">
        <xsl:with-param name="decorate" select="false()"/>
      </xsl:call-template>
      <xsl:apply-templates select="fp:owned-packageables(.)" mode="mp:packageable"/>
    </pim:component>
  </xsl:template>

  <!-- the pim:classifier-body group of the context classifier -->
  <xsl:template name="tp:classifier-body" as="element()*">
    <xsl:param name="decorate" as="xs:boolean" select="true()"/>
    <xsl:if test="$decorate">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
    </xsl:if>
    <xsl:apply-templates select="generalization" mode="mp:feature"/>
    <xsl:variable name="id" as="xs:string" select="fp:id(.)"/>
    <xsl:call-template name="tp:classifier-provides"><xsl:with-param name="id" select="$id"/></xsl:call-template>
    <xsl:call-template name="tp:classifier-requires"><xsl:with-param name="id" select="$id"/></xsl:call-template>
    <xsl:call-template name="tp:classifier-features"><xsl:with-param name="id" select="$id"/></xsl:call-template>
  </xsl:template>

  <!-- pim:provides: the realizations whose client is this classifier (the
       client is the implementing classifier, wherever the XMI put the
       element; an owned one without a client counts for its owner), and
       the provided interfaces of exposed ports -->
  <xsl:template name="tp:classifier-provides" as="element(pim:provides)*">
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="realizations" as="element()*"
        select="interfaceRealization[empty(fp:ref-ids(., 'client'))]
                | key('fp:dep-by-client', $id)[@x:type = ('InterfaceRealization', 'Realization')]"/>
    <xsl:for-each select="$realizations">
      <xsl:variable name="realization" as="element()" select="."/>
      <!-- a realization with several clients gives each its own ids -->
      <xsl:variable name="count" as="xs:integer"
          select="count((fp:ref-ids(., 'contract'), fp:ref-ids(.,'supplier')[empty(fp:ref-ids($realization, 'contract'))]))"/>
      <xsl:for-each select="fp:realized-interfaces(.)">
        <xsl:variable name="pair-id" as="xs:string"
            select="fp:pair-id($realization, fp:ref-ids($realization, 'client'), $id, $count, position())"/>
        <pim:provides id="{$pair-id}" interface="{fp:id(.)}">
          <xsl:if test="$pair-id eq fp:id($realization)">
            <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="$realization"/></xsl:call-template>
          </xsl:if>
        </pim:provides>
      </xsl:for-each>
    </xsl:for-each>
    <xsl:for-each select="fp:exposed(., 'provided')">
      <xsl:variable name="exposed" as="element()" select="."/>
      <xsl:for-each select="fp:interface-of(.)">
        <pim:provides id="{fp:id($exposed)}" interface="{fp:id(.)}"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:template>

  <!-- pim:requires: the Usages whose client is this classifier (a Usage
       with several clients gives each its own ids), and the required
       interfaces of exposed ports -->
  <xsl:template name="tp:classifier-requires" as="element(pim:requires)*">
    <xsl:param name="id" as="xs:string"/>
    <xsl:for-each select="key('fp:dep-by-client', $id)[@x:type eq 'Usage']">
      <xsl:variable name="usage" as="element()" select="."/>
      <xsl:variable name="count" as="xs:integer" select="count(fp:ref-ids(., 'supplier'))"/>
      <xsl:for-each select="fp:used-interfaces(.)">
        <xsl:variable name="pair-id" as="xs:string"
            select="fp:pair-id($usage, fp:ref-ids($usage, 'client'), $id, $count, position())"/>
        <pim:requires id="{$pair-id}" interface="{fp:id(.)}">
          <xsl:if test="$pair-id eq fp:id($usage)">
            <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="$usage"/></xsl:call-template>
          </xsl:if>
        </pim:requires>
      </xsl:for-each>
    </xsl:for-each>
    <xsl:for-each select="fp:exposed(., 'required')">
      <xsl:variable name="exposed" as="element()" select="."/>
      <xsl:for-each select="fp:interface-of(.)">
        <pim:requires id="{fp:id($exposed)}" interface="{fp:id(.)}"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:template>

  <!-- the structural features: attributes, ports, parts (of a Class or a
       Component), operations and connectors, including connectors a tool
       wrote elsewhere (Visual Paradigm: under the Model) that belong to
       the classifier owning the parts they join -->
  <xsl:template name="tp:classifier-features" as="element()*">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:param name="href-types" as="map(*)" tunnel="yes"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="properties" as="element()*" select="ownedAttribute[not(@x:type = 'Port')]"/>
    <xsl:variable name="parts" as="element()*"
        select="if (fp:meta(.) = ('Class', 'Component')) then $properties[fp:is-part(.)] else ()"/>
    <!-- an interface's datum given by the pattern it binds, or its
         messages when it is a message set (dialects.xsl) -->
    <xsl:variable name="messages" as="xs:boolean" select="fp:meta(.) eq 'Interface' and exists(fp:message-dialect(.))"/>
    <xsl:sequence select="if (fp:meta(.) eq 'Interface') then fp:pattern-datum(., $root) else ()"/>
    <xsl:sequence select="if ($messages) then fp:message-data(., $root, $href-types) else ()"/>
    <xsl:apply-templates select="$properties except $parts" mode="mp:feature"/>
    <xsl:apply-templates select="(ownedAttribute | ownedPort)[@x:type eq 'Port']" mode="mp:feature"/>
    <xsl:for-each select="$parts">
      <pim:part id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
        <xsl:sequence select="fp:typed(., $href-types)"/>
        <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
        <xsl:sequence select="fp:part-values(.)"/>
      </pim:part>
    </xsl:for-each>
    <xsl:apply-templates select="ownedOperation[not($messages)]" mode="mp:feature"/>
    <!-- the operation of a request / response pattern it binds (dialects.xsl;
         only an interface with a template binding binds one) -->
    <xsl:sequence select="if (fp:meta(.) eq 'Interface' and templateBinding) then fp:pattern-operation(., $root) else ()"/>
    <xsl:apply-templates select="ownedConnector[not(end/role/@href or end/partWithPort/@href)]"
        mode="mp:feature"/>
    <xsl:apply-templates select="key('fp:stray-connector', $id)[not(end/role/@href or end/partWithPort/@href)]"
        mode="mp:feature">
      <xsl:with-param name="owner" select="."/>
    </xsl:apply-templates>
  </xsl:template>

  <!-- the values a part sets on the properties of its type (UML's way: the
       part's defaultValue is an InstanceValue whose InstanceSpecification
       has a Slot per property, definingFeature = the property, value = a
       literal): a pim:value per slot whose property is known -->
  <xsl:function name="fp:part-values" as="element(pim:value)*">
    <xsl:param name="part" as="element()"/>
    <xsl:for-each select="$part/defaultValue[fp:meta(.) eq 'InstanceValue'] ! fp:targets(., 'instance')
                          /slot[exists(fp:targets(., 'definingFeature'))]">
      <xsl:variable name="value" as="xs:string?" select="fp:value(value[1])"/>
      <pim:value id="{fp:id(.)}" attribute="{fp:id(fp:targets(., 'definingFeature')[1])}">
        <xsl:if test="exists($value)"><xsl:attribute name="value" select="$value"/></xsl:if>
      </pim:value>
    </xsl:for-each>
  </xsl:function>

  <!-- connectors that are not an ownedConnector of a class, component or
       interface, by the classifier they belong to (fp:connector-owner) -->
  <xsl:key name="fp:stray-connector"
      match="*[@x:type eq 'Connector'][not(self::ownedConnector and ../@x:type = ('Class', 'Component', 'Interface'))]"
      use="fp:connector-owner(.)"/>

  <!-- the id of the classifier a connector belongs to: the owner of the
       first part of its ends (the first step of a SysML propertyPath, else
       partWithPort: fp:path-start), else of the first end's role -->
  <xsl:function name="fp:connector-owner" as="xs:string?">
    <xsl:param name="connection" as="element()"/>
    <xsl:variable name="owner" as="element()?"
        select="($connection/end ! fp:path-start(.), $connection/end ! fp:targets(., 'role'))[1]/.."/>
    <xsl:sequence select="$owner[@x:type = ('Class', 'Component', 'Interface')] ! fp:id(.)"/>
  </xsl:function>

  <!-- the warnings about the type of a Property or Port $e: none (IMP101),
       or a model element that is not a type (IMP102), a behaviour (IMP103:
       the attribute is a function of its owner, docs/profile.md) -->
  <xsl:template name="tp:type-warnings" as="empty-sequence()">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="typed" as="attribute()*"/>
    <xsl:variable name="meta" as="xs:string" select="fp:meta($e)"/>
    <xsl:variable name="what" as="xs:string"
        select="(if ($meta eq 'Port') then 'port ''' else 'attribute ''') || $e/@name || ''' of '
                || fp:label($e/..)"/>
    <xsl:variable name="t-meta" as="xs:string?" select="$typed[name() eq 'type-metaclass']/string()"/>
    <xsl:choose>
      <xsl:when test="empty($typed[name() = ('type', 'type-name')])">
        <!-- not of a port of a class its tool's profile says is no
             component (a Papyrus for Robotics activity's ports are untyped
             by design: they stand for the component's ports they join) -->
        <xsl:if test="($meta ne 'Port' or empty(fp:exposed($e, 'provided') | fp:exposed($e, 'required')
                                               | key('fp:dep-by-client', fp:id($e))))
                      and not($meta eq 'Port' and fp:dialect-says-component($e/..) = false())">
          <xsl:sequence select="f:warn('IMP101', fp:id($e), $what || ' has no type'
              || (if ($meta eq 'Port') then ': no data flows through it' else ': no target generates it')
              || ' (give it a type)')"/>
        </xsl:if>
      </xsl:when>
      <xsl:when test="empty($t-meta) or ($meta eq 'Port' and $t-meta eq 'Collaboration')"/>
      <xsl:when test="$t-meta = $behavior-metas and $meta ne 'Port'">
        <xsl:sequence select="f:warn('IMP103', fp:id($e), $what || ' is typed by the ' || $t-meta || ' '''
            || $typed[name() eq 'type-name'] || ''': imported as a function of '
            || fp:label($e/..) || ' (docs/profile.md); no target generates code for it yet')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="f:warn('IMP102', fp:id($e), $what || ' is typed by the ' || $t-meta || ' '''
            || $typed[name() eq 'type-name'] || ''', which is not a type robomda reads'
            || (if ($meta eq 'Port') then ' (a port is typed by an interface, a protocol (Collaboration), a class'
                                          || ' or a data type): no data flows through it'
                else ': no target generates it'))"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <!-- a property typed by a class or component is a part when it is
       composite (UML's way), or when a connector of its owner ends on a
       port of it (partWithPort), or when its owner and its type are both
       components in a dialect's profile (RobotML draws a system's parts
       with no aggregation) -->
  <xsl:function name="fp:is-part" as="xs:boolean">
    <xsl:param name="item" as="element()"/>
    <xsl:variable name="type" as="element()?" select="fp:type-element($item)"/>
    <xsl:variable name="href-type" as="element()?" select="$item/type[@href][1]"/>
    <xsl:sequence select="exists(($type, $href-type))
        and (fp:meta(($type, $href-type)[1]) = ('Class', 'Component'))
        and not(fp:dialect-says-component($item) = false() or ($type ! fp:dialect-says-component(.)) = false())
        and ($item/@aggregation = 'composite'
             or exists(key('fp:end-by-part', fp:id($item), root($item)))
             or (($type ! fp:dialect-says-component(.)) and fp:dialect-says-component($item/..)))"/>
  </xsl:function>

  <!-- connector ends by the part they name (partWithPort) -->
  <xsl:key name="fp:end-by-part" match="*[@x:type eq 'Connector']/end[@partWithPort or partWithPort]"
      use="fp:ref-ids(., 'partWithPort')"/>

  <!-- the interfaces an InterfaceRealization or Realization realizes -->
  <xsl:function name="fp:realized-interfaces" as="element()*">
    <xsl:param name="realization" as="element()"/>
    <xsl:variable name="contract" as="element()*" select="fp:targets($realization, 'contract')"/>
    <xsl:variable name="all" as="element()*"
        select="(if (exists($contract)) then $contract else fp:targets($realization, 'supplier')) ! fp:interface-of(.)"/>
    <xsl:sequence select="$all/."/>
  </xsl:function>

  <!-- the interfaces a Usage uses -->
  <xsl:function name="fp:used-interfaces" as="element()*">
    <xsl:param name="usage" as="element()"/>
    <xsl:sequence select="(fp:targets($usage, 'supplier') ! fp:interface-of(.))/."/>
  </xsl:function>

  <!-- ============================================ deployment sequence -->
  <!-- true when $d is a plain Dependency that says "client starts after
       supplier": the robomda stereotype StartAfter (recognised by the XML
       prefix robomda or the profile URI, as every later stage does), else
       the name startAfter (unprofiled models, docs/profile.md) -->
  <xsl:function name="fp:is-start-after" as="xs:boolean">
    <xsl:param name="deployment" as="element()"/>
    <xsl:sequence select="$deployment/@x:type eq 'Dependency'
        and (lower-case(normalize-space($deployment/@name)) eq 'startafter'
             or exists(key('fp:stereotype-by-base', fp:id($deployment), root($deployment))
                       [local-name() eq 'StartAfter']
                       [f:is-robomda-profile(string(prefix-from-QName(node-name(.))), namespace-uri())]))"/>
  </xsl:function>

  <!-- true when $d is a plain Dependency whose suppliers are all Devices:
       its clients (parts, components) drive that hardware (seed 001) -->
  <xsl:function name="fp:drives-device" as="xs:boolean">
    <xsl:param name="dependency" as="element()"/>
    <xsl:variable name="suppliers" as="element()*" select="fp:targets($dependency, 'supplier')"/>
    <xsl:sequence select="$dependency/@x:type eq 'Dependency' and exists($suppliers)
                          and (every $s in $suppliers satisfies fp:meta($s) eq 'Device')"/>
  </xsl:function>

  <xsl:template match="*[@x:type eq 'Dependency']" mode="mp:packageable"
                as="element(pim:dependency)?">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:variable name="start-after" as="xs:boolean" select="fp:is-start-after(.)"/>
    <xsl:variable name="drives" as="xs:boolean" select="not($start-after) and fp:drives-device(.)"/>
    <xsl:choose>
      <xsl:when test="not($start-after or $drives)"/>
      <!-- without a client or a supplier in the model: not imported
           (IMP111, report.xsl) -->
      <xsl:when test="empty(fp:targets(., 'client')) or empty(fp:targets(., 'supplier'))"/>
      <xsl:otherwise>
        <pim:dependency id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
          <xsl:if test="$drives"><xsl:attribute name="kind" select="'drives'"/></xsl:if>
          <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
          <xsl:for-each select="fp:targets(., 'client')">
            <pim:client element="{fp:id(.)}"/>
          </xsl:for-each>
          <xsl:for-each select="fp:targets(., 'supplier')">
            <pim:supplier element="{fp:id(.)}"/>
          </xsl:for-each>
        </pim:dependency>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <!-- ========================================================= features -->
  <xsl:template match="generalization" mode="mp:feature" as="element(pim:generalization)?">
    <xsl:variable name="generalization" as="element()" select="."/>
    <xsl:for-each select="fp:targets(., 'general')[1]">
      <pim:generalization id="{fp:id($generalization)}" general="{fp:id(.)}"/>
    </xsl:for-each>
  </xsl:template>

  <xsl:template match="ownedAttribute | ownedEnd" mode="mp:feature" as="element(pim:attribute)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:param name="href-types" as="map(*)" tunnel="yes"/>
    <xsl:variable name="typed" as="attribute()*" select="fp:typed(., $href-types)"/>
    <xsl:call-template name="tp:type-warnings">
      <xsl:with-param name="e" select="."/>
      <xsl:with-param name="typed" select="$typed"/>
    </xsl:call-template>
    <pim:attribute id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:sequence select="$typed"/>
      <xsl:attribute name="visibility" select="fp:visibility(.)"/>
      <xsl:attribute name="static" select="fp:bool(@isStatic, false())"/>
      <xsl:attribute name="read-only" select="fp:bool(@isReadOnly, false())"/>
      <xsl:attribute name="aggregation"
          select="if (@aggregation = ('shared', 'composite')) then string(@aggregation) else 'none'"/>
      <xsl:for-each select="fp:default(.)">
        <xsl:attribute name="default" select="."/>
      </xsl:for-each>
      <!-- a flow property's direction in its tool's profile (dialects.xsl) -->
      <xsl:sequence select="fp:dialect-port(.)[local-name() = ('direction', 'direction-literal', 'dialect')]"/>
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
    </pim:attribute>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'Port']" mode="mp:feature" as="element(pim:port)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:param name="href-types" as="map(*)" tunnel="yes"/>
    <xsl:variable name="id" as="xs:string" select="fp:id(.)"/>
    <xsl:variable name="typed" as="attribute()*" select="fp:typed(., $href-types)"/>
    <xsl:call-template name="tp:type-warnings">
      <xsl:with-param name="e" select="."/>
      <xsl:with-param name="typed" select="$typed"/>
    </xsl:call-template>
    <!-- a port typed by a protocol (Papyrus-RT: a Collaboration): the
         interfaces the protocol realizes are provided, those it uses are
         required; the other way round when the port is conjugated -->
    <xsl:variable name="protocol" as="element()?" select="fp:type-element(.)[@x:type eq 'Collaboration']"/>
    <!-- conjugated in UML, or by its tool's profile (RSA-RTE: «RTPort» isConjugate) -->
    <xsl:variable name="conjugated" as="xs:boolean"
        select="fp:bool(@isConjugated, false()) eq 'true' or fp:dialect-conjugated(.)"/>
    <xsl:variable name="protocol-realized" as="element()*"
        select="$protocol ! (interfaceRealization[empty(fp:ref-ids(., 'client'))]
                             | key('fp:dep-by-client', fp:id(.))[@x:type = ('InterfaceRealization', 'Realization')])"/>
    <xsl:variable name="protocol-used" as="element()*"
        select="$protocol ! key('fp:dep-by-client', fp:id(.))[@x:type eq 'Usage']"/>
    <xsl:variable name="own-realized" as="element()*"
        select="key('fp:dep-by-client', $id)[@x:type = ('InterfaceRealization', 'Realization')]"/>
    <xsl:variable name="own-used" as="element()*" select="key('fp:dep-by-client', $id)[@x:type eq 'Usage']"/>
    <xsl:variable name="provided-deps" as="element()*"
        select="$own-realized | (if ($conjugated) then $protocol-used else $protocol-realized)"/>
    <xsl:variable name="required-deps" as="element()*"
        select="$own-used | (if ($conjugated) then $protocol-realized else $protocol-used)"/>
    <xsl:variable name="port" as="element()" select="."/>
    <pim:port id="{$id}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:sequence select="$typed"/>
      <xsl:attribute name="visibility" select="fp:visibility(.)"/>
      <xsl:attribute name="conjugated" select="$conjugated"/>
      <xsl:attribute name="service" select="fp:bool(@isService, true())"/>
      <xsl:attribute name="behavior" select="fp:bool(@isBehavior, false())"/>
      <!-- the direction its tool's own profile gives it, or that it is the
           runtime's service (dialects.xsl) -->
      <xsl:sequence select="fp:dialect-port(.)"/>
      <xsl:for-each select="fp:runtime-port(.)">
        <xsl:attribute name="runtime" select="."/>
      </xsl:for-each>
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <!-- a service port of a dialect: its type is the interface it
           provides or requires, as the port's kind tag says -->
      <xsl:variable name="service-kind" as="xs:string?" select="fp:dialect-service-kind(.)"/>
      <xsl:variable name="service-type" as="element()?" select="fp:type-element(.)[@x:type eq 'Interface']"/>
      <xsl:variable name="provided" as="element()*"
          select="fp:exposed(., 'provided') ! fp:interface-of(.),
                  fp:targets(., 'provided')[@x:type eq 'Interface'],
                  $provided-deps ! fp:realized-interfaces(.),
                  $service-type[$service-kind eq 'provided']"/>
      <xsl:for-each select="distinct-values($provided ! fp:id(.))">
        <xsl:variable name="interface" as="xs:string" select="."/>
        <pim:provided interface="{$interface}">
          <xsl:call-template name="tp:via">
            <xsl:with-param name="deps" select="fp:exposed($port, 'provided')[fp:interface-of(.) ! fp:id(.) = $interface],
                $provided-deps[fp:realized-interfaces(.) ! fp:id(.) = $interface]"/>
          </xsl:call-template>
        </pim:provided>
      </xsl:for-each>
      <xsl:variable name="required" as="element()*"
          select="fp:exposed(., 'required') ! fp:interface-of(.),
                  fp:targets(., 'required')[@x:type eq 'Interface'],
                  $required-deps ! fp:used-interfaces(.),
                  $service-type[$service-kind eq 'required']"/>
      <xsl:for-each select="distinct-values($required ! fp:id(.))">
        <xsl:variable name="interface" as="xs:string" select="."/>
        <pim:required interface="{$interface}">
          <xsl:call-template name="tp:via">
            <xsl:with-param name="deps" select="fp:exposed($port, 'required')[fp:interface-of(.) ! fp:id(.) = $interface],
                $required-deps[fp:used-interfaces(.) ! fp:id(.) = $interface]"/>
          </xsl:call-template>
        </pim:required>
      </xsl:for-each>
    </pim:port>
  </xsl:template>

  <xsl:template match="ownedOperation" mode="mp:feature" as="element(pim:operation)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:param name="href-types" as="map(*)" tunnel="yes"/>
    <!-- a parameter's qualified name is its operation's and its own name
         (fp:qname), not the path from the root again per parameter -->
    <xsl:variable name="qname" as="xs:string" select="fp:qname(., $root)"/>
    <pim:operation id="{fp:id(.)}" name="{@name}" qualified-name="{$qname}"
        visibility="{fp:visibility(.)}" static="{fp:bool(@isStatic, false())}"
        abstract="{fp:bool(@isAbstract, false())}" query="{fp:bool(@isQuery, false())}">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <!-- a void return parameter is no return (EA writes one for every
           operation) -->
      <xsl:for-each select="ownedParameter">
        <xsl:variable name="typed" as="attribute()*" select="fp:typed(., $href-types)"/>
        <xsl:if test="not(@direction = 'return' and $typed[name() eq 'primitive'] = 'void')">
          <pim:parameter id="{fp:id(.)}" name="{@name}" qualified-name="{$qname}::{@name}">
            <xsl:sequence select="$typed"/>
            <xsl:attribute name="direction"
                select="if (@direction = ('in', 'out', 'inout', 'return')) then string(@direction) else 'in'"/>
            <xsl:for-each select="fp:default(.)">
              <xsl:attribute name="default" select="."/>
            </xsl:for-each>
            <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
          </pim:parameter>
        </xsl:if>
      </xsl:for-each>
    </pim:operation>
  </xsl:template>

  <!-- @via: the ids of the dependencies $deps that give a port its
       provided or required interface, and of its EA exposed interfaces
       (<provided>, <required>) that name it -->
  <xsl:template name="tp:via" as="attribute()?">
    <xsl:param name="deps" as="element()*"/>
    <xsl:if test="exists($deps)">
      <xsl:attribute name="via" select="distinct-values($deps ! fp:id(.))"/>
    </xsl:if>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'Connector']" mode="mp:feature" as="element(pim:connector)?">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <!-- the classifier the connector belongs to -->
    <xsl:param name="owner" as="element()" select=".."/>
    <xsl:variable name="ends" as="element()*" select="end[exists(fp:targets(., 'role'))]"/>
    <!-- the path of parts of each end (connector-ends.xsl): a connector
         with an end whose path cannot be followed is not imported (IMP110) -->
    <xsl:variable name="paths" as="map(*)*" select="$ends ! fp:end-path(., $owner)"/>
    <xsl:if test="count($ends) ge 2 and empty($paths?problem)">
      <xsl:variable name="kind" as="xs:string" select="
          if (@kind = ('assembly', 'delegation')) then string(@kind)
          else if (some $end in $ends satisfies
                     (empty(fp:ref-ids($end, 'partWithPort'))
                      and (fp:targets($end, 'role')[1]/.. is $owner)
                      and fp:meta(fp:targets($end, 'role')[1]) eq 'Port'))
          then 'delegation' else 'assembly'"/>
      <pim:connector id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}" kind="{$kind}">
        <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
        <xsl:for-each select="$ends">
          <xsl:variable name="i" as="xs:integer" select="position()"/>
          <xsl:variable name="steps" as="element()*" select="$paths[$i]?steps"/>
          <pim:end id="{fp:id(.)}" role="{fp:id(fp:targets(., 'role')[1])}">
            <xsl:for-each select="$steps[last()]">
              <xsl:attribute name="part" select="fp:id(.)"/>
            </xsl:for-each>
            <xsl:if test="count($steps) gt 1">
              <xsl:attribute name="path" select="$steps ! fp:id(.)"/>
            </xsl:if>
            <!-- the SysML NestedConnectorEnd that gave the path: read -->
            <xsl:for-each select="fp:nested-end(.)[@x:id]">
              <xsl:attribute name="via" select="@x:id"/>
            </xsl:for-each>
          </pim:end>
        </xsl:for-each>
      </pim:connector>
    </xsl:if>
  </xsl:template>
</xsl:stylesheet>
